#pragma once
// What the viewer calls each of core's methods, in one place: the panel's radio
// button and its tooltip, and the work while it runs (the panel's busy line and
// the profile's worker spans). The names a user types (`--method`, the script's
// `method`) are core's (methodName); these are only labels.
#include "isotrack/extract.h"

namespace isotrack::ui {

struct MethodLabels {
    const char* choice;   // the radio button
    const char* tooltip;  // over it
    const char* work;     // the extraction while it runs
};

const MethodLabels& methodLabels(Method method);

}  // namespace isotrack::ui
