#include "command_line/vocabulary.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "isotrack/errors.h"

namespace isotrack::command_line {
namespace {

// CLI11's "{a,b,c}" after the option in --help.
std::string braced(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names) out += (out.empty() ? "{" : ",") + name;
    return out + "}";
}

template <class Enum, std::size_t N>
std::vector<std::string> namesOf(const std::array<Enum, N>& values, const char* (*nameOf)(Enum)) {
    std::vector<std::string> names;
    for (const Enum value : values) names.push_back(nameOf(value));
    return names;
}

// Accepts what `parse` accepts and `allowed` holds, plus `extraWords`; the
// message for anything else is core's when every value is allowed, else one
// naming the words this option takes.
template <class Enum>
CLI::Validator nameCheck(Enum (*parse)(const std::string&), const char* (*nameOf)(Enum), const char* what,
                         const std::vector<Enum>& allowed, std::size_t all,
                         const std::vector<std::string>& extraWords = {}) {
    std::vector<std::string> names;
    for (const Enum value : allowed) names.push_back(nameOf(value));
    names.insert(names.end(), extraWords.begin(), extraWords.end());
    const std::string expected = listOfNames(names);
    const bool everyName = allowed.size() == all && extraWords.empty();
    auto check = [=](std::string& text) -> std::string {
        if (std::find(extraWords.begin(), extraWords.end(), text) != extraWords.end()) return {};
        try {
            const Enum value = parse(text);
            if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return {};
        } catch (const InputError& error) {
            if (everyName) return error.what();
        }
        return std::string(what) + " \"" + text + "\" is not one of " + expected;
    };
    return CLI::Validator(check, braced(names));
}

}  // namespace

std::string listOfNames(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        out += i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ");
        out += names[i];
    }
    return out;
}

CLI::Option* addMethodOption(CLI::App& command, Method& method, const std::string& help,
                             const std::vector<Method>& allowed) {
    return command
        .add_option_function<std::string>(
            "--method", [&method](const std::string& text) { method = parseMethod(text); }, help)
        ->check(nameCheck(parseMethod, methodName, "method", allowed, kMethods.size()));
}

CLI::Option* addMethodListOption(CLI::App& command, const std::string& name, const std::vector<Method>& allowed,
                                 const std::vector<std::string>& extraWords,
                                 std::function<void(const std::vector<std::string>&)> set, const std::string& help) {
    return command.add_option_function<std::vector<std::string>>(name, std::move(set), help)
        ->delimiter(',')
        ->check(nameCheck(parseMethod, methodName, "method", allowed, kMethods.size(), extraWords));
}

CLI::Option* addTableOption(CLI::App& command, TableKind& table) {
    const std::vector<std::string> names = namesOf(kTableKinds, tableKindName);
    return command
        .add_option_function<std::string>(
            "--table", [&table](const std::string& text) { table = parseTableKind(text); },
            "Triangle table: " + listOfNames(names) + " (default " + tableKindName(TableKind::Consistent) + ")")
        ->check(nameCheck(parseTableKind, tableKindName, "table", {kTableKinds.begin(), kTableKinds.end()},
                          kTableKinds.size()));
}

CLI::Option* addFrameOption(CLI::App& command, WorldFrame& frame, const std::string& help) {
    return command
        .add_option_function<std::string>(
            "--frame", [&frame](const std::string& text) { frame = parseWorldFrame(text); }, help)
        ->check(nameCheck(parseWorldFrame, worldFrameName, "frame", {kWorldFrames.begin(), kWorldFrames.end()},
                          kWorldFrames.size()));
}

}  // namespace isotrack::command_line
