#include "ui/method_labels.h"

namespace isotrack::ui {

const MethodLabels& methodLabels(Method method) {
    static const MethodLabels exhaustive{"exhaustive", "marching cubes: every cell, one mesh", "marching cubes"};
    static const MethodLabels track{"track click", "click in the view: the surface there grows from the click",
                                    "tracking"};
    static const MethodLabels all{"every surface", "each connected surface on its own", "every surface"};
    static const MethodLabels tree{"contour tree",
                                   "every surface from its contour-tree arc's seed: no scan once the tree is built",
                                   "surfaces from the contour tree"};
    switch (method) {
        case Method::Exhaustive: break;
        case Method::Track: return track;
        case Method::All: return all;
        case Method::Tree: return tree;
    }
    return exhaustive;
}

}  // namespace isotrack::ui
