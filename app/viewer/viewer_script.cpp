// Running a --script session: one command after another, each frame running
// commands until one has to wait (frames, extraction, growth, a screenshot).
#include <cstdio>

#include "isotrack/fields.h"
#include "render/camera.h"
#include "viewer/memory.h"
#include "viewer/script_run.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {
namespace {

constexpr double kWaitTimeoutSeconds = 600.0;

bool on(const ScriptCommand& command) { return command.text == "on"; }

}  // namespace

void Viewer::failScript(const std::string& message) {
    if (script_->failed) return;
    script_->failed = true;
    const bool named = message.rfind(script_->script.path + ":", 0) == 0;  // already "FILE:LINE: ..."
    if (named || script_->current == nullptr) {
        std::fprintf(stderr, "isotrack: %s\n", message.c_str());
    } else {
        std::fprintf(stderr, "isotrack: %s\n", script_->script.error(*script_->current, message).what());
    }
    exitCode_ = 1;
    quit_ = true;
}

void Viewer::advanceScript() {
    ScriptRun& run = *script_;
    if (run.failed || !waitDone()) return;
    while (run.next < run.script.commands.size() && !quit_) {
        const ScriptCommand& command = run.script.commands[run.next++];
        run.current = &command;
        if (!runCommand(command)) return;
    }
}

bool Viewer::waitDone() {
    ScriptRun& run = *script_;
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - run.waitStart).count();
    if (run.wait != ScriptRun::Wait::None && run.wait != ScriptRun::Wait::Frames && waited > kWaitTimeoutSeconds) {
        throw run.script.error(*run.current, "timed out after " + std::to_string(int(kWaitTimeoutSeconds)) + " s");
    }
    switch (run.wait) {
        case ScriptRun::Wait::None: return true;
        case ScriptRun::Wait::Frames:
            if (run.framesLeft == 0) break;
            --run.framesLeft;
            return false;
        case ScriptRun::Wait::Idle:
            if (extraction_.busy() || (scene_.anyGrowing() && playing_)) return false;
            break;
        case ScriptRun::Wait::Loaded:
            if (extraction_.busy() || !scene_.volume() || scene_.volume()->source != extraction_.source()) return false;
            break;
        case ScriptRun::Wait::Screenshot:
            if (screenshotPath_) return false;
            break;
        case ScriptRun::Wait::Sweep: {
            if (run.sweepDone == run.sweepSteps) break;
            const double t = run.sweepSteps > 1 ? double(run.sweepDone) / double(run.sweepSteps - 1) : 1.0;
            apply(ui::SetIso{run.sweepFrom + t * (run.sweepTo - run.sweepFrom)});
            ++run.sweepDone;
            return false;
        }
        case ScriptRun::Wait::Click: {
            if (extraction_.busy()) return false;
            const render::FrameOptions options = frameOptions();
            const float x = std::min(run.clickX * float(options.width), float(options.width - 1));
            const float y = std::min(run.clickY * float(options.height), float(options.height - 1));
            run.wait = ScriptRun::Wait::None;
            click(x, y, run.clickTrack);
            break;
        }
    }
    run.wait = ScriptRun::Wait::None;
    return true;
}

SurfaceStructure& Viewer::surfaceAt(const ScriptCommand& command, std::size_t argument) {
    const auto index = static_cast<std::size_t>(command.numbers.at(argument));
    auto& surfaces = scene_.surfaces();
    if (index >= surfaces.size()) {
        throw script_->script.error(command, command.name + ": there is no surface " + std::to_string(index) + " (" +
                                                 std::to_string(surfaces.size()) + " surfaces)");
    }
    return *surfaces[index];
}

bool Viewer::runCommand(const ScriptCommand& c) {
    ScriptRun& run = *script_;
    run.waitStart = std::chrono::steady_clock::now();
    const std::string& name = c.name;
    auto waitFor = [&](ScriptRun::Wait wait) {
        run.wait = wait;
        return false;
    };
    if (name == "load" || name == "field") {
        if (name == "field") parseFieldSpec(c.text);  // a bad spec fails here, on its line
        extraction_.setSource(name == "load" ? VolumeSource::file(scriptInputPath(run.script, c.text))
                                             : VolumeSource::field(c.text));
        submit();
        return waitFor(ScriptRun::Wait::Loaded);
    }
    if (name == "iso")
        apply(ui::SetIso{c.numbers[0]});
    else if (name == "table")
        apply(ui::SetTable{parseTableKind(c.text)});
    else if (name == "method") {
        apply(ui::SetMethod{parseMethod(c.text)});
    } else if (name == "click") {
        run.clickX = static_cast<float>(c.numbers[0]);
        run.clickY = static_cast<float>(c.numbers[1]);
        run.clickTrack = c.text == "ctrl";
        run.wait = ScriptRun::Wait::Click;
        return waitDone();  // clicks now when nothing is being extracted
    } else if (name == "track") {
        if (extraction_.busy()) {  // as a click does: on the surfaces the worker is making
            --run.next;
            return waitFor(ScriptRun::Wait::Idle);
        }
        if (!scene_.volume()) throw run.script.error(c, "track: no volume loaded");
        const Vec3d point{c.numbers[0], c.numbers[1], c.numbers[2]};
        if (picks_.size() >= kPicksKept) picks_.erase(picks_.begin());
        picks_.push_back({{"point", point}, {"track", true}, {"hit_surface", nullptr}});
        trackFrom(point, std::nullopt);
    } else if (name == "frames") {
        const auto frames = static_cast<std::uint64_t>(c.numbers[0]);
        if (frames == 0) return true;
        run.framesLeft = frames - 1;  // this frame is the first
        return waitFor(ScriptRun::Wait::Frames);
    } else if (name == "wait") {
        return waitFor(ScriptRun::Wait::Idle);
    } else if (name == "sweep") {
        run.sweepFrom = c.numbers[0];
        run.sweepTo = c.numbers[1];
        run.sweepSteps = static_cast<std::uint64_t>(c.numbers[2]);
        run.sweepDone = 0;
        run.wait = ScriptRun::Wait::Sweep;
        waitDone();  // the first step, this frame
        return false;
    } else if (name == "screenshot") {
        screenshotPath_ = c.text;
        return waitFor(ScriptRun::Wait::Screenshot);
    } else if (name == "profile") {
        profiler_.startRecording(c.text);
    } else if (name == "checkpoint") {
        releaseFreeMemory();  // so that the resident set counts live memory, not what malloc keeps around
        nlohmann::json mark = memoryJson();
        mark["name"] = c.text;
        mark["line"] = c.line;
        checkpoints_.push_back(mark);
    } else if (name == "camera") {
        camera_ = render::parseCamera(c.text);
    } else if (name == "frame") {
        frameCamera(c.text == "selection");
    } else if (name == "select") {
        if (c.text == "none")
            apply(ui::Select{std::nullopt});
        else
            apply(ui::Select{surfaceAt(c, 0).id()});
    } else if (name == "hide" || name == "show") {
        apply(ui::SetVisible{surfaceAt(c, 0).id(), name == "show"});
    } else if (name == "isolate") {
        apply(ui::Isolate{surfaceAt(c, 0).id()});
    } else if (name == "showall") {
        apply(ui::ShowAll{});
    } else if (name == "delete") {
        apply(ui::Delete{surfaceAt(c, 0).id()});
    } else if (name == "move") {
        apply(ui::SetOffset{surfaceAt(c, 0).id(), {float(c.numbers[1]), float(c.numbers[2]), float(c.numbers[3])}});
    } else if (name == "colour" || name == "color") {
        apply(ui::SetColour{surfaceAt(c, 0).id(), {float(c.numbers[1]), float(c.numbers[2]), float(c.numbers[3])}});
    } else if (name == "export") {
        exportSurface(surfaceAt(c, 0).id(), c.text);
    } else if (name == "explode") {
        apply(ui::SetExplode{static_cast<float>(c.numbers[0])});
    } else if (name == "growth") {
        const ui::Growth::Kind kind = c.text == "play"    ? ui::Growth::Play
                                      : c.text == "pause" ? ui::Growth::Pause
                                      : c.text == "step"  ? ui::Growth::Step
                                                          : ui::Growth::Restart;
        apply(ui::Growth{kind});
    } else if (name == "cells") {
        apply(ui::SetCellsPerFrame{static_cast<int>(c.numbers[0])});
    } else if (name == "budget") {
        apply(ui::SetGrowthBudget{static_cast<float>(c.numbers[0])});
    } else if (name == "growth-colour") {
        apply(ui::SetColourByGrowth{on(c)});
    } else if (name == "wireframe") {
        apply(ui::SetWireframe{on(c)});
    } else if (name == "box") {
        apply(ui::SetBoundingBox{on(c)});
    } else if (name == "quit") {
        quit_ = true;
        return false;
    }
    return true;
}

}  // namespace isotrack::viewer
