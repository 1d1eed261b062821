#include "viewer/script.h"

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/fields.h"
#include "isotrack/tables.h"

namespace isotrack::viewer {
namespace {

namespace fs = std::filesystem;

// Argument shapes: N a number, I a surface index (integer >= 0, or one of the
// command's keywords in its place), W a word, P a path (the rest of the line,
// may hold spaces), K one of a command's keywords.
struct Syntax {
    std::string arguments;  // one letter per argument
    int optional = 0;       // how many trailing arguments may be left out
    std::set<std::string> keywords;
};

// The keywords of `table` and `method`: core's names.
template <class Enum, std::size_t N>
std::set<std::string> namesOf(const std::array<Enum, N>& values, const char* (*nameOf)(Enum)) {
    std::set<std::string> names;
    for (const Enum value : values) names.insert(nameOf(value));
    return names;
}

const std::map<std::string, Syntax>& commands() {
    static const std::map<std::string, Syntax> table = {
        {"load", {"P", 0, {}}},
        {"field", {"W", 0, {}}},
        {"iso", {"N", 0, {}}},
        {"table", {"K", 0, namesOf(kTableKinds, tableKindName)}},
        {"method", {"K", 0, namesOf(kMethods, methodName)}},
        {"click", {"NNK", 1, {"ctrl"}}},
        {"track", {"NNN", 0, {}}},
        {"frames", {"I", 0, {}}},
        {"wait", {"", 0, {}}},
        {"confirm", {"", 0, {}}},
        {"sweep", {"NNI", 0, {}}},
        {"time", {"I", 0, {}}},
        {"play", {"I", 1, {}}},
        {"speed", {"N", 0, {}}},
        {"screenshot", {"P", 0, {}}},
        {"profile", {"P", 0, {}}},
        {"checkpoint", {"W", 0, {}}},
        {"camera", {"W", 0, {}}},
        {"frame", {"K", 1, {"all", "selection"}}},
        {"select", {"I", 0, {"none"}}},
        {"hide", {"I", 0, {}}},
        {"show", {"I", 0, {}}},
        {"isolate", {"I", 0, {}}},
        {"showall", {"", 0, {}}},
        {"delete", {"I", 0, {}}},
        {"smooth", {"II", 0, {}}},
        {"decimate", {"IN", 0, {}}},
        {"undo", {"I", 0, {}}},
        {"surface-iso", {"IN", 0, {}}},
        {"min-persistence", {"N", 0, {}}},
        {"move", {"INNN", 0, {}}},
        {"colour", {"INNN", 0, {}}},
        {"color", {"INNN", 0, {}}},
        {"export", {"IP", 0, {}}},
        {"explode", {"N", 0, {}}},
        {"growth", {"K", 0, {"play", "pause", "step", "restart"}}},
        {"cells", {"I", 0, {}}},
        {"budget", {"N", 0, {}}},
        {"growth-colour", {"K", 0, {"on", "off"}}},
        {"wireframe", {"K", 0, {"on", "off"}}},
        {"box", {"K", 0, {"on", "off"}}},
        {"quit", {"", 0, {}}},
    };
    return table;
}

std::string trim(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// Words separated by blanks; when `lastTakesRest`, argument number `count`
// is the rest of the line (a path may hold spaces).
std::vector<std::string> splitArguments(const std::string& text, std::size_t count, bool lastTakesRest) {
    std::vector<std::string> words;
    std::size_t at = 0;
    while ((at = text.find_first_not_of(" \t", at)) != std::string::npos) {
        if (lastTakesRest && words.size() + 1 == count) {
            words.push_back(trim(text.substr(at)));
            break;
        }
        const std::size_t end = text.find_first_of(" \t", at);
        words.push_back(text.substr(at, end == std::string::npos ? std::string::npos : end - at));
        at = end;
    }
    return words;
}

bool parseNumber(const std::string& word, double& value) {
    const char* end = word.data() + word.size();
    const auto [ptr, error] = std::from_chars(word.data(), end, value);
    return !word.empty() && error == std::errc() && ptr == end && std::isfinite(value);
}

std::string joined(const std::set<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : "|") + w;
    return out;
}

ScriptCommand parseLine(const std::string& path, int line, const std::string& content) {
    auto fail = [&](const std::string& message) {
        return ScriptError(path + ":" + std::to_string(line) + ": " + message);
    };
    ScriptCommand command;
    command.line = line;
    command.name = content.substr(0, content.find_first_of(" \t"));
    const auto found = commands().find(command.name);
    if (found == commands().end()) throw fail("unknown command \"" + command.name + "\"");
    const Syntax& syntax = found->second;

    const std::string& shape = syntax.arguments;
    const bool lastIsPath = !shape.empty() && shape.back() == 'P';
    const std::vector<std::string> arguments =
        splitArguments(content.substr(command.name.size()), shape.size(), lastIsPath);
    const std::size_t most = shape.size(), least = shape.size() - std::size_t(syntax.optional);
    if (arguments.size() < least || arguments.size() > most) {
        const std::string expected =
            least == most ? std::to_string(most) : std::to_string(least) + " to " + std::to_string(most);
        throw fail(command.name + ": expected " + expected + " argument" + (most == 1 ? "" : "s") + ", got " +
                   std::to_string(arguments.size()));
    }
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& word = arguments[i];
        double value = 0.0;
        switch (shape[i]) {
            case 'N':
                if (!parseNumber(word, value)) throw fail(command.name + ": \"" + word + "\" is not a number");
                command.numbers.push_back(value);
                break;
            case 'I':
                if (syntax.keywords.count(word) != 0) {  // a command's word in place of the index ("select none")
                    command.text = word;
                    break;
                }
                if (!parseNumber(word, value) || value < 0.0 || value != std::floor(value) || value > 1e9) {
                    throw fail(command.name + ": \"" + word + "\" is not a whole number >= 0");
                }
                command.numbers.push_back(value);
                break;
            case 'K':
                if (syntax.keywords.count(word) == 0) {
                    throw fail(command.name + ": \"" + word + "\" is not one of " + joined(syntax.keywords));
                }
                command.text = word;
                break;
            default:  // W, P
                command.text = word;
                break;
        }
    }
    command.words = arguments;
    return command;
}

void checkCommand(const Script& script, const ScriptCommand& command) {
    if (command.name == "load") {
        const std::string resolved = scriptInputPath(script, command.text);
        std::error_code error;
        // A file, or a folder of DICOM files.
        if (!fs::is_regular_file(resolved, error) && !fs::is_directory(resolved, error)) {
            throw script.error(command, "load: no such file or folder " + command.text);
        }
    } else if (command.name == "click") {
        for (int i = 0; i < 2; ++i) {
            if (command.numbers[std::size_t(i)] < 0.0 || command.numbers[std::size_t(i)] > 1.0) {
                throw script.error(command, "click: " + command.words[std::size_t(i)] +
                                                " is outside 0..1 (a fraction of the 3D view)");
            }
        }
    } else if (command.name == "field") {
        try {
            parseFieldSpec(command.text);
        } catch (const InputError& e) {
            throw script.error(command, std::string("field: ") + e.what());
        }
    } else if (command.name == "speed" && !(command.numbers[0] > 0.0)) {
        throw script.error(command, "speed: steps per second must be more than 0");
    } else if (command.name == "sweep" && command.numbers[2] < 1.0) {
        throw script.error(command, "sweep: STEPS must be at least 1");
    }
}

}  // namespace

ScriptError Script::error(const ScriptCommand& command, const std::string& message) const {
    return ScriptError(path + ":" + std::to_string(command.line) + ": " + message);
}

std::string scriptInputPath(const Script& script, const std::string& path) {
    const fs::path given(path);
    if (given.is_absolute()) return path;
    const fs::path beside = fs::path(script.path).parent_path() / given;
    std::error_code error;
    if (fs::exists(beside, error)) return beside.lexically_normal().string();
    return path;
}

Script parseScriptText(const std::string& text, const std::string& path) {
    Script script;
    script.path = path;
    std::istringstream in(text);
    int line = 0;
    for (std::string content; std::getline(in, content);) {
        ++line;
        content = trim(content);
        if (content.empty() || content[0] == '#') continue;
        script.commands.push_back(parseLine(path, line, content));
        checkCommand(script, script.commands.back());
    }
    return script;
}

Script parseScript(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ScriptError(path + ": cannot read the script");
    std::ostringstream text;
    text << file.rdbuf();
    return parseScriptText(text.str(), path);
}

}  // namespace isotrack::viewer
