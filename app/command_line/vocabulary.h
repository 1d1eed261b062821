#pragma once
// Options that take one of core's names: a method, a triangle table, a frame.
// The option holds core's enum; the names, and the one-line message for any
// other word, come from core (kMethods and parseMethod, kTableKinds and
// parseTableKind, kWorldFrames and parseWorldFrame), so the commands and the
// viewer accept exactly the words core does and compare no names themselves.
// A word that is not accepted fails while the command line is parsed, before
// any volume is read.
#include <functional>
#include <string>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/orientation.h"
#include "isotrack/tables.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace isotrack::command_line {

// "mc, track or all": names joined for help texts and messages.
std::string listOfNames(const std::vector<std::string>& names);

// --method NAME, one of `allowed` (every method unless given).
CLI::Option* addMethodOption(CLI::App& command, Method& method, const std::string& help,
                             const std::vector<Method>& allowed = {kMethods.begin(), kMethods.end()});

// --methods NAME,... for bench: each one of `allowed`, or one of `extraWords`
// (bench's "stream"); `set` receives the words in order, checked.
CLI::Option* addMethodListOption(CLI::App& command, const std::string& name, const std::vector<Method>& allowed,
                                 const std::vector<std::string>& extraWords,
                                 std::function<void(const std::vector<std::string>&)> set, const std::string& help);

// --table consistent|classic|trilinear.
CLI::Option* addTableOption(CLI::App& command, TableKind& table);

// --frame lps|ras|voxel (any case).
CLI::Option* addFrameOption(CLI::App& command, WorldFrame& frame, const std::string& help);

}  // namespace isotrack::command_line
