// SPDX-License-Identifier: Apache-2.0
// The engine's GL programs and the GL objects they read: the batched occlusion pass
// (light_coverage.comp), the texture-mask reduction (sunmap_coverage.comp) and the instanced
// flare draw (light_flare.vert), each linked with the light_view.glsl prelude and with its
// uniform locations looked up once.
#pragma once

#include <epoxy/gl.h>

#include "flarekit/Result.h"
#include "flarekit/Temporal.h"
#include "flarekit/flarekit.h"
#include "gl/GlObjects.h"

namespace flarekit::engine {

namespace detail {
inline void deleteSampler(GLuint n) {
    glDeleteSamplers(1, &n);
}
}  // namespace detail
using Sampler = gl::Name<detail::deleteSampler>;

//! A sampler of `filter` that clamps and never compares (a shadow-map depth texture with
//! compare mode on would read as 0/1 through texelFetch otherwise).
Sampler makeSampler(GLenum filter);
//! Immutable storage the CPU may rewrite (glNamedBufferSubData).
gl::Buffer makeBuffer(GLsizeiptr bytes);

//! The uniforms both occlusion passes take from light_view.glsl and light_state.glsl.
struct LightPassUniforms {
    GLint view = -1, projection = -1, viewport = -1, convention = -1, viewIndex = -1,
          stateBase = -1, attack = -1, release = -1, guardBand = -1;

    void locate(GLuint n) {
        view = gl::uniformLocation(n, "viewMatrix");
        projection = gl::uniformLocation(n, "projectionMatrix");
        viewport = gl::uniformLocation(n, "viewport");
        convention = gl::uniformLocation(n, "depthConvention");
        viewIndex = gl::uniformLocation(n, "viewIndex");
        stateBase = gl::uniformLocation(n, "stateBase");
        attack = gl::uniformLocation(n, "attackStep");
        release = gl::uniformLocation(n, "releaseStep");
        guardBand = gl::uniformLocation(n, "depthPastViewport");
    }
    //! View `index` of a frame: its matrices, viewport and convention, its rows of the state,
    //! the filter's steps for its dt, and whether depth past its viewport may be read.
    void set(GLuint p, const fk_frame& f, int index, int maxLights, const TemporalParams& t,
             bool pastViewport) const {
        glProgramUniformMatrix4fv(p, view, 1, GL_FALSE, f.view);
        glProgramUniformMatrix4fv(p, projection, 1, GL_FALSE, f.projection);
        glProgramUniform4iv(p, viewport, 1, f.viewport);
        glProgramUniform1i(p, convention, int(f.depth_convention));
        glProgramUniform1i(p, viewIndex, index);
        glProgramUniform1i(p, stateBase, index * maxLights);
        glProgramUniform1f(p, attack, float(smoothingStep(f.dt_seconds, t.attackSeconds)));
        glProgramUniform1f(p, release, float(smoothingStep(f.dt_seconds, t.releaseSeconds)));
        glProgramUniform1i(p, guardBand, pastViewport ? 1 : 0);
    }
};

//! The batched occlusion pass on a frame's depth, single-sample or multisampled.
struct CoverageProgram {
    gl::Program program;
    LightPassUniforms pass;
    GLint perSide = -1, hasTransmittance = -1, textureSize = -1, sampleCount = -1,
          samplePositions = -1, depthSamples = -1;
};

Result<CoverageProgram> linkCoverage(bool multisample);

//! The texture-mask reduction (sunmap_coverage.comp) and its uniforms.
struct SunMapProgram {
    gl::Program program;
    LightPassUniforms pass;
    GLint tileSize = -1, tilesPerRow = -1;
};

Result<SunMapProgram> linkSunMap();

//! The instanced flare draw (engine/FlareDraw.h).
struct FlareProgram {
    gl::Program program;
    GLint view = -1, projection = -1, viewport = -1, convention = -1, viewIndex = -1, presetId = -1,
          t = -1, halfSize = -1, guardBand = -1, referenceFlux = -1, edgeStreak = -1, reach = -1,
          coverageChannel = -1, fadeAtEdges = -1;
};

Result<FlareProgram> linkFlare();

}  // namespace flarekit::engine
