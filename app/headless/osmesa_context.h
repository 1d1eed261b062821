#pragma once
// An OpenGL 3.3 core context through Mesa's OSMesa (llvmpipe on the CPU), the
// reference for the golden images. libOSMesa is opened at run time, so machines
// without it (a GPU box with only its vendor's driver) still start.
#include <memory>

#include "gl/check.h"

namespace isotrack::headless {

class OsmesaContext {
public:
    // Creates the context and makes it current on this thread; throws gl::Error
    // when libOSMesa is missing (or isotrack was built without its headers) or fails.
    OsmesaContext();
    ~OsmesaContext();
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    // OSMesaGetProcAddress, for gl::loadFunctions.
    static gl::ProcAddress procAddress(const char* name);

private:
    struct Handles;
    std::unique_ptr<Handles> handles_;
};

}  // namespace isotrack::headless
