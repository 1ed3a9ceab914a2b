// SPDX-License-Identifier: Apache-2.0
// The one list of GPU visibility methods: each method's contract name and the factory that
// builds it (in src/occlusion/GpuVisibility.cpp, GL). The GL-free core reads the names from it
// (validation, --help, "built without OpenGL" messages); the GL library reads the factories.
#pragma once

//! X(name, factory) for every method, in the order --help lists them.
#define FLAREKIT_GPU_METHODS(X)                     \
    X("readback", makeReadback)                     \
    X("pbo", makePbo)                               \
    X("query", makeQuery)                           \
    X("texture-mask", makeTextureMask)              \
    X("texture-mask-screen", makeTextureMaskScreen) \
    X("burnout", makeBurnout)                       \
    X("compute", makeCompute)
