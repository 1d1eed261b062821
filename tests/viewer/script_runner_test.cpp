// The script runner against a fake host: what each command asks of the viewer,
// on which frame, what it waits for, and errors that name the script's line.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "viewer/script_runner.h"

using namespace isotrack;
using namespace isotrack::viewer;

namespace {

// Records what the runner asks; the waits look at the public flags.
struct FakeHost : ScriptHost {
    bool busy = false, growingNow = false, shown = true, volume = true, screenshot = false, playing = false;
    std::vector<std::uint32_t> ids;  // surface ids in list order
    std::vector<ui::Action> actions;
    std::vector<std::string> calls;
    ScriptRunner* runner = nullptr;  // told about submitted requests, as the viewer does

    bool extracting() const override { return busy; }
    bool growing() const override { return growingNow; }
    bool sourceShown() const override { return shown; }
    bool hasVolume() const override { return volume; }
    bool screenshotPending() const override { return screenshot; }
    bool timePlaying() const override { return playing; }
    std::size_t surfaceCount() const override { return ids.size(); }
    std::uint32_t surfaceId(std::size_t index) const override { return ids.at(index); }

    void apply(const ui::Action& action) override { actions.push_back(action); }
    void load(const VolumeSource& source) override {
        calls.push_back(std::string(source.kind == VolumeSource::Kind::Field ? "field " : "file ") + source.text);
        if (runner != nullptr) runner->noteSubmitted();
    }
    void clickView(float fx, float fy, bool track) override {
        calls.push_back("click " + std::to_string(fx) + " " + std::to_string(fy) + (track ? " track" : ""));
    }
    void trackPoint(const Vec3d& p) override {
        calls.push_back("track " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]));
    }
    void requestScreenshot(const std::string& path) override {
        screenshot = true;
        calls.push_back("screenshot " + path);
    }
    void startProfile(const std::string& path) override { calls.push_back("profile " + path); }
    void checkpoint(const std::string& name, int line) override {
        calls.push_back("checkpoint " + name + " line " + std::to_string(line));
    }
    void setCamera(const std::string& spec) override { calls.push_back("camera " + spec); }
    void frameCamera(bool selectionOnly) override { calls.push_back(selectionOnly ? "frame selection" : "frame all"); }
    void exportSurface(std::uint32_t id, const std::string& path) override {
        calls.push_back("export " + std::to_string(id) + " " + path);
    }
    void quit() override { calls.push_back("quit"); }
    void fail(const std::string& message) override { calls.push_back("fail " + message); }
};

// A runner over `text` (as s.isotrack) driving `host`.
struct Session {
    FakeHost host;
    ScriptRunner runner;
    explicit Session(const std::string& text) : runner(parseScriptText(text, "s.isotrack"), host) {
        host.runner = &runner;
    }
    // One frame's script step; a thrown error goes to fail(), as the viewer's frame does.
    void frame() {
        try {
            runner.advance();
        } catch (const std::exception& e) {
            runner.fail(e.what());
        }
    }
};

std::vector<double> isoValues(const std::vector<ui::Action>& actions) {
    std::vector<double> values;
    for (const ui::Action& action : actions) {
        if (const auto* iso = std::get_if<ui::SetIso>(&action)) values.push_back(iso->iso);
    }
    return values;
}

}  // namespace

TEST_CASE("commands that need no wait all run in one frame, as actions and host calls", "[viewer][script]") {
    Session s(
        "iso 0.25\ntable classic\nmethod track\nselect 1\nselect none\nhide 0\nshow 1\nisolate 1\nshowall\n"
        "delete 0\nmove 1 1 -2 3.5\ncolour 0 1 0.5 0\nexplode 0.5\ngrowth step\ncells 100\nbudget 8\n"
        "growth-colour on\nwireframe on\nbox off\ncamera -60,22,100,1,2,3\nframe selection\nframe\n"
        "profile trace.json\ncheckpoint warm\nexport 1 out.ply\nsurface-iso 1 0.6\n"
        "min-persistence 0.125\n");
    s.host.ids = {10, 11};
    s.frame();
    CHECK(s.runner.finished());
    CHECK_FALSE(s.runner.failed());
    const std::vector<ui::Action>& a = s.host.actions;
    REQUIRE(a.size() == 21);
    CHECK(std::get<ui::SetIso>(a[0]).iso == 0.25);
    CHECK(std::get<ui::SetTable>(a[1]).table == ui::Table::Classic);
    CHECK(std::get<ui::SetMethod>(a[2]).method == ui::Method::Track);
    CHECK(std::get<ui::Select>(a[3]).id == std::optional<std::uint32_t>(11));  // index 1 is id 11
    CHECK_FALSE(std::get<ui::Select>(a[4]).id.has_value());
    CHECK(std::get<ui::SetVisible>(a[5]).id == 10);
    CHECK_FALSE(std::get<ui::SetVisible>(a[5]).visible);
    CHECK(std::get<ui::SetVisible>(a[6]).visible);
    CHECK(std::get<ui::Isolate>(a[7]).id == 11);
    CHECK(std::holds_alternative<ui::ShowAll>(a[8]));
    CHECK(std::get<ui::Delete>(a[9]).id == 10);
    CHECK(std::get<ui::SetOffset>(a[10]).offset == std::array<float, 3>{1.0f, -2.0f, 3.5f});
    CHECK(std::get<ui::SetColour>(a[11]).colour == std::array<float, 3>{1.0f, 0.5f, 0.0f});
    CHECK(std::get<ui::SetExplode>(a[12]).factor == 0.5f);
    CHECK(std::get<ui::Growth>(a[13]).kind == ui::Growth::Step);
    CHECK(std::get<ui::SetCellsPerFrame>(a[14]).cells == 100);
    CHECK(std::get<ui::SetGrowthBudget>(a[15]).ms == 8.0f);
    CHECK(std::get<ui::SetColourByGrowth>(a[16]).on);
    CHECK(std::get<ui::SetWireframe>(a[17]).on);
    CHECK_FALSE(std::get<ui::SetBoundingBox>(a[18]).on);
    CHECK(std::get<ui::SetSurfaceIso>(a[19]).id == 11);  // surface index 1, its own isovalue
    CHECK(std::get<ui::SetSurfaceIso>(a[19]).iso == 0.6);
    CHECK(std::get<ui::SetMinPersistence>(a[20]).persistence == 0.125);
    CHECK(s.host.calls == std::vector<std::string>{"camera -60,22,100,1,2,3", "frame selection", "frame all",
                                                   "profile trace.json", "checkpoint warm line 24",
                                                   "export 11 out.ply"});
}

TEST_CASE("load and field wait until the worker is done and the scene shows the source", "[viewer][script]") {
    Session s("field sphere:16\niso 1\n");
    CHECK(s.runner.loadsFirst());
    s.host.busy = true;
    s.host.shown = false;
    s.frame();
    CHECK(s.host.calls == std::vector<std::string>{"field sphere:16"});
    s.host.busy = false;
    s.frame();  // the worker is done but its volume is not shown yet
    CHECK(s.host.actions.empty());
    s.host.shown = true;
    s.frame();
    CHECK(isoValues(s.host.actions) == std::vector<double>{1.0});
    CHECK(s.runner.finished());
    CHECK_FALSE(Session("iso 1\nfield sphere:16\n").runner.loadsFirst());
}

TEST_CASE("load DIR asks the host for the folder as a file source", "[viewer][script]") {
    const std::string folder = std::filesystem::temp_directory_path().string();  // any folder passes the parser
    Session s("load " + folder + "\n");
    CHECK(s.runner.loadsFirst());
    s.frame();
    CHECK(s.host.calls == std::vector<std::string>{"file " + folder});
}

TEST_CASE("frames N takes N frames, this one the first", "[viewer][script]") {
    Session s("frames 3\niso 1\nframes 0\niso 2\n");
    for (int frame = 1; frame <= 3; ++frame) {
        s.frame();
        CHECK(s.host.actions.empty());
    }
    s.frame();  // the fourth frame runs the rest: "frames 0" waits for nothing
    CHECK(isoValues(s.host.actions) == std::vector<double>{1.0, 2.0});
}

TEST_CASE("a sweep sets one isovalue per frame, from FROM to TO", "[viewer][script]") {
    Session s("sweep 0 1 3\niso 5\n");
    s.frame();
    CHECK(isoValues(s.host.actions) == std::vector<double>{0.0});
    s.frame();
    s.frame();
    CHECK(isoValues(s.host.actions) == std::vector<double>{0.0, 0.5, 1.0});
    s.frame();
    CHECK(isoValues(s.host.actions) == std::vector<double>{0.0, 0.5, 1.0, 5.0});
    Session one("sweep 0 1 1\n");
    one.frame();
    CHECK(isoValues(one.host.actions) == std::vector<double>{1.0});  // one step goes straight to TO
}

TEST_CASE("clicks and track wait for the extraction in progress", "[viewer][script]") {
    Session s("click 0.5 0.25 ctrl\ntrack 1 2 3\nclick 0 1\n");
    s.host.busy = true;
    s.frame();
    s.frame();
    CHECK(s.host.calls.empty());
    s.host.busy = false;
    s.frame();
    CHECK(s.host.calls == std::vector<std::string>{"click 0.500000 0.250000 track", "track 1.000000 2.000000 3.000000",
                                                   "click 0.000000 1.000000"});

    Session t("iso 1\ntrack 1 2 3\niso 2\n");
    t.host.busy = true;
    t.frame();  // track is put back until the worker is done
    CHECK(isoValues(t.host.actions) == std::vector<double>{1.0});
    t.host.busy = false;
    t.frame();
    CHECK(t.host.calls.size() == 1);
    CHECK(isoValues(t.host.actions) == std::vector<double>{1.0, 2.0});
}

TEST_CASE("confirm waits for the method's request to reach the worker, then confirms", "[viewer][script]") {
    Session s("method all\nconfirm\niso 2\n");
    s.host.busy = true;
    s.frame();  // the request for all is on its way: confirm is put back
    REQUIRE(s.host.actions.size() == 1);
    CHECK(std::holds_alternative<ui::SetMethod>(s.host.actions[0]));
    s.frame();
    CHECK(s.host.actions.size() == 1);
    s.host.busy = false;
    s.frame();
    REQUIRE(s.host.actions.size() == 3);
    CHECK(std::holds_alternative<ui::ConfirmExtraction>(s.host.actions[1]));
    CHECK(isoValues(s.host.actions) == std::vector<double>{2.0});
}

TEST_CASE("wait waits for extraction and for growth; screenshot for the picture", "[viewer][script]") {
    Session s("wait\niso 1\nscreenshot a b.png\niso 2\n");
    s.host.growingNow = true;
    s.frame();
    s.frame();
    CHECK(s.host.actions.empty());
    s.host.growingNow = false;
    s.frame();
    CHECK(isoValues(s.host.actions) == std::vector<double>{1.0});
    CHECK(s.host.calls == std::vector<std::string>{"screenshot a b.png"});
    s.frame();
    CHECK(isoValues(s.host.actions).size() == 1);  // the screenshot is not written yet
    s.host.screenshot = false;
    s.frame();
    CHECK(isoValues(s.host.actions) == std::vector<double>{1.0, 2.0});
}

TEST_CASE("quit ends the session: later commands do not run", "[viewer][script]") {
    Session s("iso 1\nquit\niso 2\n");
    s.frame();
    s.frame();
    CHECK(s.runner.finished());
    CHECK(s.host.calls == std::vector<std::string>{"quit"});
    CHECK(isoValues(s.host.actions) == std::vector<double>{1.0});
}

TEST_CASE("errors while running name the script's line, once", "[viewer][script]") {
    Session s("field sphere:16\nmethod track\nwait\nhide 3\niso 1\n");
    s.frame();  // field, waits for the volume
    s.frame();  // method, waits for the extraction
    s.frame();  // hide fails
    REQUIRE(s.runner.failed());
    CHECK(s.host.calls.back() == "fail s.isotrack:4: hide: there is no surface 3 (0 surfaces)");
    s.runner.fail("a second error");
    s.frame();
    CHECK(s.host.calls.back() == "fail s.isotrack:4: hide: there is no surface 3 (0 surfaces)");
    CHECK(isoValues(s.host.actions).empty());

    Session plain("iso 1\n");
    plain.frame();
    plain.runner.fail("screenshot.png: cannot write");  // a message without the script's name gets its line
    CHECK(plain.host.calls.back() == "fail s.isotrack:1: screenshot.png: cannot write");

    Session noVolume("track 1 2 3\n");
    noVolume.host.volume = false;
    noVolume.frame();
    CHECK(noVolume.host.calls.back() == "fail s.isotrack:1: track: no volume loaded");
}

TEST_CASE("an extraction error names the command that asked for it", "[viewer][script]") {
    Session s("field sphere:16\niso 1\n");
    s.frame();
    s.frame();
    CHECK(std::string(s.runner.extractionError("cannot read").what()) == "s.isotrack:1: cannot read");
    Session none("iso 1\n");
    none.frame();  // no request came from the script: the current command is named
    CHECK(std::string(none.runner.extractionError("cannot read").what()) == "s.isotrack:1: cannot read");
}

TEST_CASE("time waits until its step is shown; play until playback and extraction end", "[viewer][script]") {
    Session s("speed 8\ntime 3\nplay 2\nplay\niso 1\n");
    s.host.busy = true;
    s.host.shown = false;
    s.frame();
    REQUIRE(s.host.actions.size() == 2);
    CHECK(std::get<ui::SetTimeSpeed>(s.host.actions[0]).stepsPerSecond == 8.0f);
    CHECK(std::get<ui::SetTimeStep>(s.host.actions[1]).step == 3);
    s.host.busy = false;
    s.frame();  // not shown yet
    CHECK(s.host.actions.size() == 2);
    s.host.shown = true;
    s.host.playing = true;
    s.frame();
    REQUIRE(s.host.actions.size() == 3);
    const auto& play = std::get<ui::PlayTime>(s.host.actions[2]);
    CHECK(play.play);
    CHECK(play.steps == std::optional<std::size_t>(2));
    s.host.playing = false;
    s.host.busy = true;  // the last step's extraction still running
    s.frame();
    CHECK(s.host.actions.size() == 3);
    s.host.busy = false;
    s.frame();
    REQUIRE(s.host.actions.size() == 4);
    CHECK_FALSE(std::get<ui::PlayTime>(s.host.actions[3]).steps.has_value());  // to the last step
    s.host.playing = true;
    s.frame();
    CHECK(s.host.actions.size() == 4);
    s.host.playing = false;
    s.frame();
    CHECK(isoValues(s.host.actions) == std::vector<double>{1.0});
    CHECK(s.runner.finished());
}
