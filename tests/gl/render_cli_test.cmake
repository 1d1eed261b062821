# `isotrack render --gl osmesa` writes byte-identical PNGs for identical inputs, and refuses
# bad sizes with a one-line message and exit status 1.
#   cmake -DISOTRACK=<isotrack> -DOUT_DIR=<dir> -P render_cli_test.cmake
file(MAKE_DIRECTORY ${OUT_DIR})
foreach(run a b)
  execute_process(
    COMMAND ${ISOTRACK} render --gl osmesa --field blobs:32 --method all --size 160x120 --wireframe --out ${OUT_DIR}/${run}.png
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "isotrack render failed (${status}): ${out}${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT_DIR}/a.png ${OUT_DIR}/b.png RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "two renders of the same input differ: ${OUT_DIR}/a.png ${OUT_DIR}/b.png")
endif()

foreach(size 0x10 10x9000 10 axb 10x10x10)
  execute_process(COMMAND ${ISOTRACK} render --field sphere:16 --size ${size} --out ${OUT_DIR}/bad.png
                  RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 1 OR NOT err MATCHES "^isotrack: --size")
    message(FATAL_ERROR "--size ${size}: expected exit 1 and 'isotrack: --size ...', got ${status}: ${err}")
  endif()
endforeach()
message(STATUS "isotrack render is deterministic and validates --size")
