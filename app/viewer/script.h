#pragma once
// Scripted sessions: `isotrack --script FILE` runs one command per line in the
// real window. Blank lines and lines starting with '#' are skipped. Surfaces
// are named by their index I in the panel's list (0 first; for "every surface"
// that is the largest). Input paths (load) are looked up next to the script
// first, then in the current directory; output paths (screenshot, profile,
// export) are relative to the current directory.
//
//   load PATH                 load a volume file; waits until it is loaded
//   field NAME[:N]            build a built-in field; waits until it is built
//   iso V                     set the isovalue (re-extracts in the background)
//   table consistent|classic  method mc|track|all
//   click FX FY [ctrl]        click at fractions of the 3D view (0..1, origin top-left),
//                             after any extraction in progress has finished
//   track X Y Z               track the surface nearest the world point (as ctrl-click does),
//                             after any extraction in progress has finished
//   frames N                  run N frames
//   wait                      run frames until extraction and growth are done
//   confirm                   let the method read a volume over the memory budget (the
//                             panel's Extract), after any extraction in progress has finished;
//                             an error when no extraction waits for it
//   sweep FROM TO STEPS       set the isovalue on each of STEPS frames, FROM to TO
//   time STEP                 a time series: show step STEP; waits until it is shown
//   play [N]                  a time series: play N steps (or to the last); waits until played
//   speed S                   playback speed, S steps per second
//   screenshot PATH           the whole window, panel included, as PNG
//   profile PATH              record a Chrome trace from here on, written at the end
//   checkpoint NAME           note CPU, GPU and resident bytes for the --json summary
//   camera YAW,PITCH,DISTANCE,TX,TY,TZ[,FOV]    frame [all|selection]
//   select I|none  hide I  show I  isolate I  showall  delete I
//   min-persistence P         method tree: hide surfaces whose arc's persistence is below P
//   surface-iso I V           method tree: surface I at its own isovalue V (only it is tracked again)
//   move I DX DY DZ  colour I R G B  export I PATH  explode F
//   smooth I N  decimate I R  undo I    surface I's mesh smoothed (N iterations) or
//                             decimated (to R of its triangles), as extract does; undo the last
//   growth play|pause|step|restart  cells N  budget MS  growth-colour on|off
//   wireframe on|off  box on|off
//   quit                      close the window and end the session
//
// Errors name the script and the line: "FILE:LINE: what is wrong".
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace isotrack::viewer {

class ScriptError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ScriptCommand {
    int line = 0;
    std::string name;                // the command word
    std::vector<std::string> words;  // its arguments as written
    std::vector<double> numbers;     // the numeric arguments, parsed
    std::string text;                // the text argument (path, spec, keyword)
};

struct Script {
    std::string path;
    std::vector<ScriptCommand> commands;

    // "FILE:LINE: message", for errors found while running.
    ScriptError error(const ScriptCommand& command, const std::string& message) const;
};

// Reads and checks every line: known command, argument count, numbers that
// parse, and that files to load exist. Throws ScriptError on the first problem.
Script parseScript(const std::string& path);
Script parseScriptText(const std::string& text, const std::string& path);

// An input path as the script means it: next to the script if it exists there,
// else as given.
std::string scriptInputPath(const Script& script, const std::string& path);

}  // namespace isotrack::viewer
