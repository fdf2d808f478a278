#pragma once
// A whole budget run of the LOD driver (spec §3.3) with the default criterion, for the tests of what
// a budget means.
#include <cstddef>

#include <gtest/gtest.h>

#include "rgb/lod/lod_driver.h"
#include "rgb/mesh/mesh.h"

namespace rgbtest {

inline rgb::LodReport run_budget(rgb::Mesh& mesh, std::size_t budget, int cap = rgb::kMaxLevel) {
    rgb::LodSettings settings;
    settings.max_triangles = budget;
    settings.max_level = cap;
    rgb::LodDriver driver(mesh, settings);
    driver.run();
    EXPECT_TRUE(driver.done());
    return driver.report();
}

}  // namespace rgbtest
