// The script parser: every command of the syntax, and errors that name the
// script and the line.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "viewer/script.h"

using namespace isotrack::viewer;

namespace {

std::string errorOf(const std::string& text) {
    try {
        parseScriptText(text, "s.isotrack");
    } catch (const ScriptError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("a script of every command parses, skipping comments and blank lines", "[viewer][script]") {
    const Script script = parseScriptText(
        "# a comment\n"
        "\n"
        "field blobs:32\n"
        "iso 0.25\n"
        "table classic\n"
        "method track\n"
        "click 0.5 0.25 ctrl\n"
        "click 0 1\n"
        "frames 10\n"
        "wait\n"
        "sweep 0.1 0.4 20\n"
        "screenshot out dir/shot one.png\n"
        "profile trace.json\n"
        "checkpoint warm\n"
        "camera -60,22,100,1,2,3\n"
        "frame selection\n"
        "frame\n"
        "select none\n"
        "select 2\n"
        "hide 1\nshow 1\nisolate 0\nshowall\ndelete 0\n"
        "move 0 1 -2 3.5\n"
        "colour 0 1 0.5 0\n"
        "export 0 surface.ply\n"
        "explode 0.5\n"
        "growth pause\ncells 100\nbudget 8\ngrowth-colour on\nwireframe off\nbox on\n"
        "quit\n",
        "s.isotrack");
    REQUIRE(script.commands.size() == 33);
    CHECK(script.commands[0].name == "field");
    CHECK(script.commands[0].line == 3);
    CHECK(script.commands[0].text == "blobs:32");
    CHECK(script.commands[1].numbers == std::vector<double>{0.25});
    CHECK(script.commands[4].numbers == std::vector<double>{0.5, 0.25});
    CHECK(script.commands[4].text == "ctrl");
    CHECK(script.commands[5].text.empty());
    CHECK(script.commands[9].text == "out dir/shot one.png");  // a path is the rest of the line
    CHECK(script.commands[13].text == "selection");
    CHECK(script.commands[14].text.empty());  // frame, with its optional keyword left out
    CHECK(script.commands[15].text == "none");
    CHECK(script.commands[16].numbers == std::vector<double>{2});
    CHECK(script.commands.back().name == "quit");
}

TEST_CASE("surface-iso takes a surface index and an isovalue", "[viewer][script]") {
    const Script script = parseScriptText("method tree\nsurface-iso 3 0.45\n", "s.isotrack");
    REQUIRE(script.commands.size() == 2);
    CHECK(script.commands[1].name == "surface-iso");
    CHECK(script.commands[1].numbers == std::vector<double>{3, 0.45});
    CHECK_THAT(errorOf("surface-iso 3"), Catch::StartsWith("s.isotrack:1: surface-iso"));
    CHECK(errorOf("surface-iso x 0.4") == "s.isotrack:1: surface-iso: \"x\" is not a whole number >= 0");
}

TEST_CASE("time takes a step, play an optional count, speed steps per second", "[viewer][script]") {
    const Script script = parseScriptText("time 3\nplay\nplay 4\nspeed 2.5\n", "s.isotrack");
    REQUIRE(script.commands.size() == 4);
    CHECK(script.commands[0].numbers == std::vector<double>{3});
    CHECK(script.commands[1].numbers.empty());
    CHECK(script.commands[2].numbers == std::vector<double>{4});
    CHECK(script.commands[3].numbers == std::vector<double>{2.5});
    CHECK(errorOf("time -1") == "s.isotrack:1: time: \"-1\" is not a whole number >= 0");
    CHECK(errorOf("play 1 2") == "s.isotrack:1: play: expected 0 to 1 argument, got 2");
    CHECK(errorOf("speed 0") == "s.isotrack:1: speed: steps per second must be more than 0");
}

TEST_CASE("script errors name the file and the line", "[viewer][script]") {
    CHECK(errorOf("iso 1\nfrobnicate\n") == "s.isotrack:2: unknown command \"frobnicate\"");
    CHECK(errorOf("\n\niso one\n") == "s.isotrack:3: iso: \"one\" is not a number");
    CHECK(errorOf("frames -2") == "s.isotrack:1: frames: \"-2\" is not a whole number >= 0");
    CHECK(errorOf("frames 1.5") == "s.isotrack:1: frames: \"1.5\" is not a whole number >= 0");
    CHECK(errorOf("select -1") == "s.isotrack:1: select: \"-1\" is not a whole number >= 0");
    CHECK(errorOf("select 1.7") == "s.isotrack:1: select: \"1.7\" is not a whole number >= 0");
    CHECK(errorOf("method fast") == "s.isotrack:1: method: \"fast\" is not one of all|mc|track|tree");
    CHECK(errorOf("click 0.5") == "s.isotrack:1: click: expected 2 to 3 arguments, got 1");
    CHECK(errorOf("click 0.5 1.2") == "s.isotrack:1: click: 1.2 is outside 0..1 (a fraction of the 3D view)");
    CHECK(errorOf("quit now") == "s.isotrack:1: quit: expected 0 arguments, got 1");
    CHECK(errorOf("load missing/volume.nrrd") == "s.isotrack:1: load: no such file or folder missing/volume.nrrd");
    CHECK_THAT(errorOf("field teapot"), Catch::StartsWith("s.isotrack:1: field: "));
    CHECK(errorOf("iso nan") == "s.isotrack:1: iso: \"nan\" is not a number");
}

TEST_CASE("input paths are looked up next to the script first", "[viewer][script]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "isotrack_script_test";
    fs::create_directories(dir / "sub");
    std::ofstream(dir / "volume.nrrd") << "not really";
    std::ofstream(dir / "sub" / "s.isotrack") << "load ../volume.nrrd\n";
    const Script script = parseScript((dir / "sub" / "s.isotrack").string());
    REQUIRE(script.commands.size() == 1);
    CHECK(fs::equivalent(scriptInputPath(script, script.commands[0].text), dir / "volume.nrrd"));
    CHECK(scriptInputPath(script, "/abs/path.nrrd") == "/abs/path.nrrd");
    CHECK_THROWS_WITH(parseScript((dir / "none.isotrack").string()), Catch::Contains("cannot read the script"));
    fs::remove_all(dir);
}

TEST_CASE("load takes a folder (a DICOM series) as well as a file", "[viewer][script]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "isotrack_script_folder_test";
    fs::create_directories(dir / "series");
    std::ofstream(dir / "s.isotrack") << "load series\n";
    const Script script = parseScript((dir / "s.isotrack").string());
    REQUIRE(script.commands.size() == 1);
    CHECK(fs::equivalent(scriptInputPath(script, script.commands[0].text), dir / "series"));
    CHECK(errorOf("load " + (dir / "gone").string()) ==
          "s.isotrack:1: load: no such file or folder " + (dir / "gone").string());
    fs::remove_all(dir);
}
