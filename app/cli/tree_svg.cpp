#include "cli/tree_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace isotrack::cli {
namespace {

constexpr double kWidth = 800, kHeight = 600, kMargin = 40;

std::string hexColour(const std::array<float, 3>& rgb) {
    char text[8];
    auto byte = [](float c) { return static_cast<int>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
    std::snprintf(text, sizeof(text), "#%02x%02x%02x", byte(rgb[0]), byte(rgb[1]), byte(rgb[2]));
    return text;
}

}  // namespace

std::string treeSvg(const TreeLayout& layout, const std::vector<PlottedSurface>& surfaces, double at) {
    auto px = [](double x) { return kMargin + (kWidth - 2 * kMargin) * x; };
    auto py = [&](double v) {
        const double t = std::clamp((v - layout.lo) / (layout.hi - layout.lo), 0.0, 1.0);
        return kHeight - kMargin - (kHeight - 2 * kMargin) * t;
    };
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    for (const TreeLayout::Link& link : layout.links) {
        svg << "<line class=\"link\" x1=\"" << px(link.x0) << "\" y1=\"" << py(link.value) << "\" x2=\"" << px(link.x1)
            << "\" y2=\"" << py(link.value) << "\" stroke=\"#ccc\" stroke-width=\"1\"/>\n";
    }
    for (std::size_t b = 0; b < layout.branchLines.size(); ++b) {
        const TreeLayout::BranchLine& line = layout.branchLines[b];
        svg << "<line class=\"branch\" data-branch=\"" << b << "\" data-arcs=\"" << line.arcs << "\" x1=\""
            << px(line.x) << "\" y1=\"" << py(line.lower) << "\" x2=\"" << px(line.x) << "\" y2=\"" << py(line.upper)
            << "\" stroke=\"#999\" stroke-width=\"1\"/>\n";
    }
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        const TreeLayout::Segment* segment = layout.segmentOf(surfaces[s].arc);
        if (!segment) continue;
        svg << "<line class=\"arc\" data-arc=\"" << segment->arc << "\" data-surface=\"" << s << "\" x1=\""
            << px(segment->x) << "\" y1=\"" << py(segment->lower) << "\" x2=\"" << px(segment->x) << "\" y2=\""
            << py(segment->upper) << "\" stroke=\"" << hexColour(surfaces[s].colour) << "\" stroke-width=\"3\"/>\n";
    }
    svg << "<line class=\"iso\" x1=\"0\" x2=\"" << kWidth << "\" y1=\"" << py(at) << "\" y2=\"" << py(at)
        << "\" stroke=\"black\" stroke-dasharray=\"4 3\"/>\n";
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        const TreeLayout::Segment* segment = layout.segmentOf(surfaces[s].arc);
        if (!segment) continue;
        svg << "<circle class=\"surface\" data-surface=\"" << s << "\" cx=\"" << px(segment->x) << "\" cy=\""
            << py(surfaces[s].iso) << "\" r=\"4\" fill=\"" << hexColour(surfaces[s].colour)
            << "\" stroke=\"black\"/>\n";
    }
    svg << "<text x=\"4\" y=\"" << py(at) - 4 << "\" font-size=\"12\">iso " << at << ": " << surfaces.size()
        << " surfaces</text>\n"
        << "<text x=\"4\" y=\"14\" font-size=\"12\">" << layout.hi << "</text><text x=\"4\" y=\"" << kHeight - 4
        << "\" font-size=\"12\">" << layout.lo << "</text>\n";
    if (layout.hiddenArcs + layout.prunedArcs > 0) {
        svg << "<text x=\"" << kWidth - 4 << "\" y=\"14\" font-size=\"12\" text-anchor=\"end\">"
            << layout.hiddenArcs + layout.prunedArcs << " arcs hidden</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace isotrack::cli
