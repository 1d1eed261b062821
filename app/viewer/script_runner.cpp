#include "viewer/script_runner.h"

#include <algorithm>
#include <optional>

#include "isotrack/extract.h"
#include "isotrack/fields.h"

namespace isotrack::viewer {
namespace {

constexpr double kWaitTimeoutSeconds = 600.0;

bool on(const ScriptCommand& command) { return command.text == "on"; }

ui::Growth::Kind growthKind(const std::string& word) {
    return word == "play"    ? ui::Growth::Play
           : word == "pause" ? ui::Growth::Pause
           : word == "step"  ? ui::Growth::Step
                             : ui::Growth::Restart;
}

}  // namespace

bool ScriptRunner::loadsFirst() const {
    if (script_.commands.empty()) return false;
    const std::string& first = script_.commands.front().name;
    return first == "load" || first == "field";
}

void ScriptRunner::fail(const std::string& message) {
    if (failed_) return;
    failed_ = true;
    const bool named = message.rfind(script_.path + ":", 0) == 0;  // already "FILE:LINE: ..."
    if (named || current_ == nullptr) {
        host_.fail(message);
    } else {
        host_.fail(script_.error(*current_, message).what());
    }
}

ScriptError ScriptRunner::extractionError(const std::string& message) const {
    const ScriptCommand* command = jobCommand_ ? jobCommand_ : current_;
    return command ? script_.error(*command, message) : ScriptError(message);
}

void ScriptRunner::advance() {
    if (failed_ || !waitDone()) return;
    while (next_ < script_.commands.size() && !quit_) {
        const ScriptCommand& command = script_.commands[next_++];
        current_ = &command;
        if (!runCommand(command)) return;
    }
}

bool ScriptRunner::waitDone() {
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - waitStart_).count();
    if (wait_ != Wait::None && wait_ != Wait::Frames && waited > kWaitTimeoutSeconds) {
        throw script_.error(*current_, "timed out after " + std::to_string(int(kWaitTimeoutSeconds)) + " s");
    }
    switch (wait_) {
        case Wait::None: return true;
        case Wait::Frames:
            if (framesLeft_ == 0) break;
            --framesLeft_;
            return false;
        case Wait::Idle:
            if (host_.extracting() || host_.growing()) return false;
            break;
        case Wait::Loaded:
            if (host_.extracting() || !host_.sourceShown()) return false;
            break;
        case Wait::Screenshot:
            if (host_.screenshotPending()) return false;
            break;
        case Wait::Sweep: {
            if (sweepDone_ == sweepSteps_) break;
            const double t = sweepSteps_ > 1 ? double(sweepDone_) / double(sweepSteps_ - 1) : 1.0;
            host_.apply(ui::SetIso{sweepFrom_ + t * (sweepTo_ - sweepFrom_)});
            ++sweepDone_;
            return false;
        }
        case Wait::Play:
            if (host_.timePlaying() || host_.extracting()) return false;
            break;
        case Wait::Click:
            if (host_.extracting()) return false;
            wait_ = Wait::None;  // before clicking: a click that throws is not retried
            host_.clickView(clickX_, clickY_, clickTrack_);
            break;
    }
    wait_ = Wait::None;
    return true;
}

bool ScriptRunner::waitFor(Wait wait) {
    wait_ = wait;
    return false;
}

std::uint32_t ScriptRunner::surfaceAt(const ScriptCommand& command, std::size_t argument) const {
    const auto index = static_cast<std::size_t>(command.numbers.at(argument));
    const std::size_t count = host_.surfaceCount();
    if (index >= count) {
        throw script_.error(command, command.name + ": there is no surface " + std::to_string(index) + " (" +
                                         std::to_string(count) + " surfaces)");
    }
    return host_.surfaceId(index);
}

bool ScriptRunner::runCommand(const ScriptCommand& c) {
    waitStart_ = std::chrono::steady_clock::now();
    const std::string& name = c.name;
    if (name == "load" || name == "field") {
        if (name == "field") parseFieldSpec(c.text);  // a bad spec fails here, on its line
        host_.load(name == "load" ? VolumeSource::file(scriptInputPath(script_, c.text)) : VolumeSource::field(c.text));
        return waitFor(Wait::Loaded);
    }
    if (name == "iso") {
        host_.apply(ui::SetIso{c.numbers[0]});
    } else if (name == "table") {
        host_.apply(ui::SetTable{parseTableKind(c.text)});
    } else if (name == "method") {
        host_.apply(ui::SetMethod{parseMethod(c.text)});
    } else if (name == "click") {
        clickX_ = static_cast<float>(c.numbers[0]);
        clickY_ = static_cast<float>(c.numbers[1]);
        clickTrack_ = c.text == "ctrl";
        wait_ = Wait::Click;
        return waitDone();  // clicks now when nothing is being extracted
    } else if (name == "track") {
        if (host_.extracting()) {  // as a click does: on the surfaces the worker is making
            --next_;
            return waitFor(Wait::Idle);
        }
        if (!host_.hasVolume()) throw script_.error(c, "track: no volume loaded");
        host_.trackPoint(Vec3d{c.numbers[0], c.numbers[1], c.numbers[2]});
    } else if (name == "confirm") {
        if (host_.extracting()) {  // the method's request reaches the worker's gate first
            --next_;
            return waitFor(Wait::Idle);
        }
        host_.apply(ui::ConfirmExtraction{});
    } else if (name == "frames") {
        const auto frames = static_cast<std::uint64_t>(c.numbers[0]);
        if (frames == 0) return true;
        framesLeft_ = frames - 1;  // this frame is the first
        return waitFor(Wait::Frames);
    } else if (name == "wait") {
        return waitFor(Wait::Idle);
    } else if (name == "sweep") {
        sweepFrom_ = c.numbers[0];
        sweepTo_ = c.numbers[1];
        sweepSteps_ = static_cast<std::uint64_t>(c.numbers[2]);
        sweepDone_ = 0;
        wait_ = Wait::Sweep;
        waitDone();  // the first step, this frame
        return false;
    } else if (name == "time") {
        host_.apply(ui::SetTimeStep{static_cast<std::size_t>(c.numbers[0])});
        return waitFor(Wait::Loaded);
    } else if (name == "play") {
        const std::optional<std::size_t> steps =
            c.numbers.empty() ? std::nullopt : std::optional<std::size_t>(static_cast<std::size_t>(c.numbers[0]));
        host_.apply(ui::PlayTime{true, steps});
        return waitFor(Wait::Play);
    } else if (name == "speed") {
        host_.apply(ui::SetTimeSpeed{static_cast<float>(c.numbers[0])});
    } else if (name == "screenshot") {
        host_.requestScreenshot(c.text);
        return waitFor(Wait::Screenshot);
    } else if (name == "profile") {
        host_.startProfile(c.text);
    } else if (name == "checkpoint") {
        host_.checkpoint(c.text, c.line);
    } else if (name == "camera") {
        host_.setCamera(c.text);
    } else if (name == "frame") {
        host_.frameCamera(c.text == "selection");
    } else if (name == "select") {
        host_.apply(ui::Select{c.text == "none" ? std::nullopt : std::optional<std::uint32_t>(surfaceAt(c, 0))});
    } else if (name == "hide" || name == "show") {
        host_.apply(ui::SetVisible{surfaceAt(c, 0), name == "show"});
    } else if (name == "isolate") {
        host_.apply(ui::Isolate{surfaceAt(c, 0)});
    } else if (name == "showall") {
        host_.apply(ui::ShowAll{});
    } else if (name == "delete") {
        host_.apply(ui::Delete{surfaceAt(c, 0)});
    } else if (name == "smooth") {
        host_.apply(ui::ProcessMesh{surfaceAt(c, 0), static_cast<int>(c.numbers[1]), 1.0});
    } else if (name == "decimate") {
        host_.apply(ui::ProcessMesh{surfaceAt(c, 0), 0, c.numbers[1]});
    } else if (name == "undo") {
        host_.apply(ui::UndoMesh{surfaceAt(c, 0)});
    } else if (name == "min-persistence") {
        host_.apply(ui::SetMinPersistence{c.numbers[0]});
    } else if (name == "surface-iso") {
        host_.apply(ui::SetSurfaceIso{surfaceAt(c, 0), c.numbers[1]});
    } else if (name == "move") {
        host_.apply(ui::SetOffset{surfaceAt(c, 0), {float(c.numbers[1]), float(c.numbers[2]), float(c.numbers[3])}});
    } else if (name == "colour" || name == "color") {
        host_.apply(ui::SetColour{surfaceAt(c, 0), {float(c.numbers[1]), float(c.numbers[2]), float(c.numbers[3])}});
    } else if (name == "export") {
        host_.exportSurface(surfaceAt(c, 0), c.text);
    } else if (name == "explode") {
        host_.apply(ui::SetExplode{static_cast<float>(c.numbers[0])});
    } else if (name == "growth") {
        host_.apply(ui::Growth{growthKind(c.text)});
    } else if (name == "cells") {
        host_.apply(ui::SetCellsPerFrame{static_cast<int>(c.numbers[0])});
    } else if (name == "budget") {
        host_.apply(ui::SetGrowthBudget{static_cast<float>(c.numbers[0])});
    } else if (name == "growth-colour") {
        host_.apply(ui::SetColourByGrowth{on(c)});
    } else if (name == "wireframe") {
        host_.apply(ui::SetWireframe{on(c)});
    } else if (name == "box") {
        host_.apply(ui::SetBoundingBox{on(c)});
    } else if (name == "quit") {
        quit_ = true;
        host_.quit();
        return false;
    }
    return true;
}

}  // namespace isotrack::viewer
