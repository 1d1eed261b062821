// Volumes for the 3-state table's tests: integer samples in [-range, range]
// (at isovalue 0 many samples equal it, and at 0.5 many crossings lie near a
// sample, so every snapping pass has work), and float noise in [-1, 1].
#pragma once

#include <random>

#include "isotrack/volume.h"

namespace isotrack::test {

inline Volume randomIntegers(const Dims& dims, std::mt19937& rng, int range) {
    Volume v(dims, ScalarType::Int16);
    std::uniform_int_distribution<int> pick(-range, range);
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x) v.setValue(x, y, z, pick(rng));
    return v;
}

inline Volume randomFloats(const Dims& dims, std::mt19937& rng) {
    Volume v(dims, ScalarType::Float32);
    std::uniform_real_distribution<double> pick(-1.0, 1.0);
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x) v.setValue(x, y, z, pick(rng));
    return v;
}

}  // namespace isotrack::test
