#pragma once
// How the panel writes numbers.
#include <cstddef>
#include <string>

namespace isotrack::ui {

// "12.3 MB", "512 B".
std::string formatBytes(std::size_t bytes);
// "12.3 ms", or "--" when timings are frozen or unknown (< 0).
std::string formatMs(double ms, bool frozen);
// "1,234,567".
std::string formatCount(std::size_t count);

}  // namespace isotrack::ui
