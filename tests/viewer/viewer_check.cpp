// Checks on what a scripted viewer session leaves behind, for the viewer tests
// (tests/viewer/*.sh run the session under Xvfb, then this):
//
//   viewer_check golden ACTUAL.png NAME     window screenshot against tests/golden/NAME.png
//   viewer_check summary FILE.json [--surfaces N] [--min-frames N] [--tracked]
//   viewer_check profile FILE.json --min-frames N
//   viewer_check soak FILE.json WARM END --max-rss-growth BYTES   (checkpoint name prefixes)
//   viewer_check field FILE.json KEY        print a number from the summary
//   viewer_check surfaces FILE.json         one line per surface: index id triangles tracked selected
//                                           state visible
//   viewer_check others-unchanged FILE.json BEFORE AFTER ID
//       (checkpoint names) the same surface ids at both, each with the same triangles, but surface
//       ID, whose triangles must differ (the only surface whose isovalue changed)
//   viewer_check same-arcs FILE.json BEFORE AFTER
//       (checkpoint names) the same surface ids at both, each on the same contour-tree arc
//   viewer_check sweep FILE.json PROFILE.json BEFORE STILL SWEPT DONE --min-applied N
//       (checkpoint names) extractions applied from STILL to DONE must be at least N; prints the
//       median frame time from STILL to SWEPT (the isovalue moving) against BEFORE to STILL (not)
//
// Golden metric: the screenshot (the whole window, panel included, taken with
// --deterministic so the panel's timings read "--") is reduced 3x by averaging
// 3x3 blocks (960x600 -> 320x200, the size the baselines are kept at), then a
// pixel differs when any channel differs from the baseline by more than 12 of
// 255, and the image fails when more than 0.5% of its pixels differ. The
// reduction and the slack absorb llvmpipe's rounding and glyph anti-aliasing
// differences, not a changed panel, surface or colour. On failure the reduced
// image and a diff image (red: differing pixels) are written next to ACTUAL and
// both paths printed; a missing baseline fails and writes the reduced image.
// ISOTRACK_UPDATE_GOLDEN=1 writes the baseline instead: look at it first.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "golden_compare.h"
#include "render/image.h"

using isotrack::render::Image;
using nlohmann::json;

namespace {

constexpr int kReduction = 3;
constexpr int kChannelTolerance = 12;
constexpr double kMaxDifferentFraction = 0.005;

int fail(const std::string& message) {
    std::fprintf(stderr, "viewer_check: %s\n", message.c_str());
    return 1;
}

json readJson(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw std::runtime_error(path + ": cannot read");
    return json::parse(file);
}

Image reduce(const Image& image) {
    Image out(image.width / kReduction, image.height / kReduction);
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int dy = 0; dy < kReduction; ++dy) {
                    for (int dx = 0; dx < kReduction; ++dx)
                        sum += image.pixel(x * kReduction + dx, y * kReduction + dy)[c];
                }
                out.pixel(x, y)[c] = static_cast<std::uint8_t>(sum / (kReduction * kReduction));
            }
        }
    }
    return out;
}

int golden(const std::string& actualPath, const std::string& name) {
    const std::string stem = std::filesystem::path(actualPath).replace_extension().string();
    isotrack::test::GoldenPolicy policy;
    policy.baseline = std::string(ISOTRACK_GOLDEN_DIR) + "/" + name + ".png";
    policy.actualPath = stem + ".reduced.png";
    policy.diffPath = stem + ".diff.png";
    policy.channelTolerance = kChannelTolerance;
    policy.maxDifferentFraction = kMaxDifferentFraction;
    const isotrack::test::GoldenVerdict verdict =
        isotrack::test::checkGoldenImage(reduce(isotrack::render::readPng(actualPath)), name, policy);
    if (!verdict.passed) return fail(verdict.message);
    std::printf("%s\n", verdict.message.c_str());
    return 0;
}

int summary(int argc, char** argv) {
    const json s = readJson(argv[2]);
    for (const char* key : {"surfaces", "cpu_bytes", "gpu_bytes", "frames", "median_frame_ms"}) {
        if (!s.contains(key)) return fail(std::string("summary has no \"") + key + "\"");
    }
    for (const json& surface : s["surfaces"]) {
        for (const char* key : {"id", "triangles", "vertices", "bytes"}) {
            if (!surface.contains(key)) return fail(std::string("a surface has no \"") + key + "\"");
        }
    }
    if (!(s["cpu_bytes"].get<double>() > 0) || !(s["gpu_bytes"].get<double>() > 0)) return fail("no CPU or GPU bytes");
    // The frame counters docs/viewer.md names: a session that drew has uploaded.
    if (!s.contains("frame_counters")) return fail("summary has no \"frame_counters\"");
    for (const char* key : {"max_draw_calls", "max_triangles_drawn", "max_uploaded_bytes", "uploaded_bytes"}) {
        if (!s["frame_counters"].contains(key)) return fail(std::string("frame_counters has no \"") + key + "\"");
    }
    if (!(s["frame_counters"]["uploaded_bytes"].get<double>() > 0)) return fail("frame_counters: nothing uploaded");
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string option = argv[i];
        const long value = std::atol(argv[i + 1]);
        if (option == "--surfaces" && long(s["surfaces"].size()) != value) {
            return fail("expected " + std::to_string(value) + " surfaces, the summary has " +
                        std::to_string(s["surfaces"].size()));
        }
        if (option == "--min-frames" && s["frames"].get<long>() < value) {
            return fail("expected at least " + std::to_string(value) + " frames, got " + s["frames"].dump());
        }
    }
    std::printf("summary: %zu surfaces, cpu_bytes %s, gpu_bytes %s, %s frames, median %.2f ms\n", s["surfaces"].size(),
                s["cpu_bytes"].dump().c_str(), s["gpu_bytes"].dump().c_str(), s["frames"].dump().c_str(),
                s["median_frame_ms"].get<double>());
    return 0;
}

// Chrome trace: an object with traceEvents; every "X" event has numeric ts and
// dur (microseconds); at least N "frame" events; stages nest inside frames.
int profile(const std::string& path, long minFrames) {
    const json trace = readJson(path);
    if (!trace.contains("traceEvents") || !trace["traceEvents"].is_array())
        return fail(path + ": no traceEvents array");
    long frames = 0, stages = 0;
    for (const json& event : trace["traceEvents"]) {
        if (!event.contains("ph") || !event.contains("name")) return fail(path + ": an event without ph or name");
        if (event["ph"] != "X") continue;
        if (!event["ts"].is_number() || !event["dur"].is_number() || event["dur"].get<double>() < 0) {
            return fail(path + ": an X event without numeric ts/dur: " + event.dump());
        }
        if (event["name"] == "frame") ++frames;
        if (event.value("cat", "") == "stage") ++stages;
    }
    std::printf("profile: %ld frame events, %ld stage events\n", frames, stages);
    if (frames < minFrames)
        return fail(path + ": " + std::to_string(frames) + " frame events, expected >= " + std::to_string(minFrames));
    if (stages < frames) return fail(path + ": fewer stage events than frames");
    return 0;
}

// The checkpoints whose names start with `prefix` (e.g. warm1, warm2, warm3).
std::vector<json> checkpoints(const json& s, const std::string& prefix) {
    std::vector<json> found;
    for (const json& c : s["checkpoints"]) {
        if (c["name"].get<std::string>().rfind(prefix, 0) == 0) found.push_back(c);
    }
    if (found.empty()) throw std::runtime_error("no checkpoint named " + prefix + "* in the summary");
    return found;
}

long lowestRss(const std::vector<json>& marks) {
    long lowest = marks.front()["rss_bytes"].get<long>();
    for (const json& m : marks) lowest = std::min(lowest, m["rss_bytes"].get<long>());
    return lowest;
}

// CPU and GPU bytes must be the same at every checkpoint; resident memory is
// compared lowest to lowest, because llvmpipe holds a few MiB of scratch at
// some moments and not at others (a two-valued wobble, not a trend).
int soak(const std::string& path, const std::string& warmPrefix, const std::string& endPrefix, long maxRssGrowth) {
    const json s = readJson(path);
    const std::vector<json> warm = checkpoints(s, warmPrefix), end = checkpoints(s, endPrefix);
    const json& first = warm.front();
    for (const std::vector<json>* marks : {&warm, &end}) {
        for (const json& m : *marks) {
            std::printf("checkpoint %-6s frame %5s: cpu_bytes %s, gpu_bytes %s, rss %s\n",
                        m["name"].get<std::string>().c_str(), m["frame"].dump().c_str(), m["cpu_bytes"].dump().c_str(),
                        m["gpu_bytes"].dump().c_str(), m["rss_bytes"].dump().c_str());
            if (m["cpu_bytes"] != first["cpu_bytes"]) return fail("CPU bytes changed between the checkpoints");
            if (m["gpu_bytes"] != first["gpu_bytes"]) return fail("GPU bytes changed between the checkpoints");
        }
    }
    const long rssGrowth = lowestRss(end) - lowestRss(warm);
    std::printf("soak: CPU and GPU bytes unchanged; lowest resident set %+ld bytes from warm-up to the end\n",
                rssGrowth);
    if (rssGrowth > maxRssGrowth) {
        return fail("resident memory grew by " + std::to_string(rssGrowth) + " bytes (limit " +
                    std::to_string(maxRssGrowth) + ")");
    }
    return 0;
}

const json& checkpoint(const json& s, const std::string& name) {
    for (const json& c : s["checkpoints"]) {
        if (c["name"] == name) return c;
    }
    throw std::runtime_error("no checkpoint named " + name + " in the summary");
}

double medianFrameMs(const json& trace, long from, long to) {
    std::vector<double> ms;
    for (const json& event : trace["traceEvents"]) {
        if (event.value("name", "") != "frame" || event.value("ph", "") != "X") continue;
        const long frame = event["args"]["frame"].get<long>();
        if (frame >= from && frame < to) ms.push_back(event["dur"].get<double>() / 1000.0);
    }
    if (ms.empty()) throw std::runtime_error("no frames " + std::to_string(from) + ".." + std::to_string(to));
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

int sweep(char** argv, long minApplied) {
    const json s = readJson(argv[2]);
    const json trace = readJson(argv[3]);
    const json &before = checkpoint(s, argv[4]), &still = checkpoint(s, argv[5]), &swept = checkpoint(s, argv[6]),
               &done = checkpoint(s, argv[7]);
    const long duringSweep = swept["extractions_applied"].get<long>() - still["extractions_applied"].get<long>();
    const long applied = done["extractions_applied"].get<long>() - still["extractions_applied"].get<long>();
    const double quiet = medianFrameMs(trace, before["frame"].get<long>(), still["frame"].get<long>());
    const double moving = medianFrameMs(trace, still["frame"].get<long>(), swept["frame"].get<long>());
    std::printf(
        "sweep: %ld frames, %ld extractions applied during it and %ld by its end; median frame %.2f ms "
        "while sweeping, %.2f ms before (%.2fx)\n",
        swept["frame"].get<long>() - still["frame"].get<long>(), duringSweep, applied, moving, quiet, moving / quiet);
    if (applied < minApplied) {
        return fail(std::to_string(applied) + " extractions applied, expected at least " + std::to_string(minApplied));
    }
    return 0;
}

int othersUnchanged(const std::string& path, const std::string& beforeName, const std::string& afterName,
                    const std::string& changed) {
    const json s = readJson(path);
    const json &before = checkpoint(s, beforeName)["surface_triangles"],
               &after = checkpoint(s, afterName)["surface_triangles"];
    if (before.size() != after.size()) {
        return fail(std::to_string(before.size()) + " surfaces at " + beforeName + ", " + std::to_string(after.size()) +
                    " at " + afterName);
    }
    std::size_t same = 0;
    for (const auto& [id, triangles] : before.items()) {
        if (!after.contains(id)) return fail("surface " + id + " is gone at " + afterName);
        if (id == changed) {
            if (after[id] == triangles) return fail("surface " + id + " kept its " + triangles.dump() + " triangles");
            continue;
        }
        if (after[id] != triangles) {
            return fail("surface " + id + " changed: " + triangles.dump() + " -> " + after[id].dump() + " triangles");
        }
        ++same;
    }
    if (!before.contains(changed)) return fail("no surface " + changed + " at " + beforeName);
    std::printf("others-unchanged: %zu surfaces keep their triangles; surface %s went from %s to %s\n", same,
                changed.c_str(), before[changed].dump().c_str(), after[changed].dump().c_str());
    return 0;
}

int sameArcs(const std::string& path, const std::string& beforeName, const std::string& afterName) {
    const json s = readJson(path);
    const json &before = checkpoint(s, beforeName)["surface_arcs"], &after = checkpoint(s, afterName)["surface_arcs"];
    if (before.empty()) return fail("no surface has an arc at " + beforeName);
    if (before != after) return fail("surface ids or arcs differ: " + before.dump() + " against " + after.dump());
    std::printf("same-arcs: %zu surfaces keep their ids and arcs\n", before.size());
    return 0;
}

int surfaces(const std::string& path) {
    const json s = readJson(path);
    std::size_t index = 0;
    for (const json& surface : s["surfaces"]) {
        std::printf("%zu %s %s %d %d %s %d\n", index++, surface["id"].dump().c_str(),
                    surface["triangles"].dump().c_str(), surface.value("tracked", false) ? 1 : 0,
                    surface.value("selected", false) ? 1 : 0, surface.value("state", std::string("shown")).c_str(),
                    surface.value("visible", true) ? 1 : 0);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string what = argc > 1 ? argv[1] : "";
        if (what == "golden" && argc == 4) return golden(argv[2], argv[3]);
        if (what == "summary" && argc >= 3) return summary(argc, argv);
        if (what == "profile" && argc == 5) return profile(argv[2], std::atol(argv[4]));
        if (what == "soak" && argc == 7) return soak(argv[2], argv[3], argv[4], std::atol(argv[6]));
        if (what == "surfaces" && argc == 3) return surfaces(argv[2]);
        if (what == "same-arcs" && argc == 5) return sameArcs(argv[2], argv[3], argv[4]);
        if (what == "others-unchanged" && argc == 6) return othersUnchanged(argv[2], argv[3], argv[4], argv[5]);
        if (what == "sweep" && argc == 10 && std::string(argv[8]) == "--min-applied") {
            return sweep(argv, std::atol(argv[9]));
        }
        if (what == "field" && argc == 4) {
            const json s = readJson(argv[2]);
            json value = s;
            for (std::string key = argv[3], rest; !key.empty(); key = rest) {
                const std::size_t dot = key.find('.');
                rest = dot == std::string::npos ? "" : key.substr(dot + 1);
                key = key.substr(0, dot);
                json next = value.is_array() ? value.at(std::stoul(key)) : value.at(key);
                value = next;
            }
            std::printf("%s\n", value.is_string() ? value.get<std::string>().c_str() : value.dump().c_str());
            return 0;
        }
        return fail("usage: see the top of tests/viewer/viewer_check.cpp");
    } catch (const std::exception& e) {
        return fail(e.what());
    }
}
