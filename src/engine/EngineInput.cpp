// SPDX-License-Identifier: Apache-2.0
#include "engine/EngineInput.h"

#include "engine/Engine.h"

#include <epoxy/gl.h>

#include <cmath>
#include <cstring>
#include <sstream>

namespace flarekit::engine {

namespace {

bool finite(const float* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

//! Directional lights' angular radius limit: the Scene JSON's (kDirectionalLightParams).
constexpr float kMaxAngularRadiusDeg = 45.f;

//! The integer a C caller stored in an enum field. Read as int, never as the C++ enum: a C
//! program may store any int there, and loading a value outside the enumerators' range
//! through the enum type is undefined behaviour in C++ (UBSan: "not a valid value").
template <class Enum>
int enumBits(const Enum& field) {
    static_assert(sizeof(Enum) == sizeof(int), "C enums are int-sized on every supported ABI");
    int bits = 0;
    std::memcpy(&bits, &field, sizeof bits);
    return bits;
}

}  // namespace

Status checkFrameNumbers(const fk_frame* frame, const std::string& at) {
    if (!frame) return invalidInput(at + ": expected a frame, got NULL");
    const fk_frame& f = *frame;
    if (const int convention = enumBits(f.depth_convention);
        convention < FK_DEPTH_MINUS_ONE_TO_ONE || convention > FK_DEPTH_REVERSED_Z) {
        return invalidInput(at + ".depth_convention: expected 0, 1 or 2 (FK_DEPTH_*), got " +
                            std::to_string(convention));
    }
    if (!finite(f.view, 16)) return invalidInput(at + ".view: expected 16 finite numbers");
    if (!finite(f.projection, 16))
        return invalidInput(at + ".projection: expected 16 finite numbers");
    if (!std::isfinite(f.dt_seconds) || f.dt_seconds < 0) {
        return invalidInput(at + ".dt_seconds: expected a finite number >= 0, got " +
                            number(f.dt_seconds));
    }
    if (f.width < 1 || f.height < 1) {
        return invalidInput(at + ".width, height: expected the depth texture's size (>= 1), got " +
                            std::to_string(f.width) + " x " + std::to_string(f.height));
    }
    const int* v = f.viewport;
    if (v[0] < 0 || v[1] < 0 || v[2] < 1 || v[3] < 1 || v[2] > f.width - v[0] ||
        v[3] > f.height - v[1]) {
        return invalidInput(at + ".viewport: expected x, y >= 0, w, h >= 1 inside the " +
                            std::to_string(f.width) + " x " + std::to_string(f.height) +
                            " depth texture, got [" + std::to_string(v[0]) + ", " +
                            std::to_string(v[1]) + ", " + std::to_string(v[2]) + ", " +
                            std::to_string(v[3]) + "]");
    }
    return Ok{};
}

Result<DepthTextureInfo> checkFrame(const fk_frame* frame, const std::string& at) {
    if (Status s = checkFrameNumbers(frame, at); !s) return s.error();
    const fk_frame& f = *frame;
    const std::string texture = at + ".depth_texture: ";
    if (f.depth_texture == 0 || !glIsTexture(f.depth_texture)) {
        return invalidInput(texture + "expected the name of a GL texture, got " +
                            std::to_string(f.depth_texture));
    }
    GLint target = 0;
    glGetTextureParameteriv(f.depth_texture, GL_TEXTURE_TARGET, &target);
    if (target != GL_TEXTURE_2D && target != GL_TEXTURE_2D_MULTISAMPLE) {
        return invalidInput(texture +
                            "expected a GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE texture");
    }
    GLint width = 0, height = 0, depthBits = 0, samples = 0;
    glGetTextureLevelParameteriv(f.depth_texture, 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(f.depth_texture, 0, GL_TEXTURE_HEIGHT, &height);
    glGetTextureLevelParameteriv(f.depth_texture, 0, GL_TEXTURE_DEPTH_SIZE, &depthBits);
    glGetTextureLevelParameteriv(f.depth_texture, 0, GL_TEXTURE_SAMPLES, &samples);
    if (depthBits <= 0) return invalidInput(texture + "expected a depth format");
    if (width != f.width || height != f.height) {
        return invalidInput(texture + "is " + std::to_string(width) + " x " +
                            std::to_string(height) + "; expected the frame's width x height, " +
                            std::to_string(f.width) + " x " + std::to_string(f.height));
    }
    DepthTextureInfo info;
    info.multisample = target == GL_TEXTURE_2D_MULTISAMPLE;
    info.samples = info.multisample ? std::max(1, int(samples)) : 1;
    if (info.samples > 16)
        return invalidInput(texture + "expected at most 16 samples, got " +
                            std::to_string(samples));
    return info;
}

Status checkSamplesPerSide(int perSide) {
    if (perSide < 1 || perSide > kMaxSamplesPerSide) {
        return invalidInput("samples_per_side: expected 1.." + std::to_string(kMaxSamplesPerSide) +
                            ", got " + std::to_string(perSide));
    }
    return Ok{};
}

Status setTemporalParams(TemporalParams& t, float attackSeconds, float releaseSeconds,
                         float guardBand) {
    TemporalParams next = t;
    next.attackSeconds = attackSeconds;
    next.releaseSeconds = releaseSeconds;
    next.guardBand = guardBand;
    if (Status s = validateTemporalParams(next); !s) return s;
    t = next;
    return Ok{};
}

Status checkLights(const fk_light* lights, int count, int maxLights, int presetCount) {
    if (count < 0 || count > maxLights) {
        return invalidInput("count: expected 0.." + std::to_string(maxLights) +
                            " (the engine's max_lights), got " + std::to_string(count));
    }
    if (count > 0 && !lights) return invalidInput("lights: expected an array, got NULL");
    for (int i = 0; i < count; ++i) {
        const fk_light& l = lights[i];
        // The field's name is built only for a message: the checks run every frame.
        const auto at = [i] { return "lights[" + std::to_string(i) + "]."; };
        if (const int type = enumBits(l.type);
            type != FK_LIGHT_DIRECTIONAL && type != FK_LIGHT_POINT) {
            return invalidInput(at() +
                                "type: expected FK_LIGHT_DIRECTIONAL (0) or FK_LIGHT_POINT "
                                "(1), got " +
                                std::to_string(type));
        }
        const bool point = l.type == FK_LIGHT_POINT;
        if (point && !finite(l.position, 3))
            return invalidInput(at() + "position: expected 3 finite numbers");
        if (!point) {
            if (!finite(l.direction, 3))
                return invalidInput(at() + "direction: expected 3 finite numbers");
            const float d2 = l.direction[0] * l.direction[0] + l.direction[1] * l.direction[1] +
                             l.direction[2] * l.direction[2];
            if (!(d2 > 0) || !std::isfinite(d2))
                return invalidInput(at() + "direction: expected a non-zero direction");
        }
        const float maxRadius = point ? 1e30f : kMaxAngularRadiusDeg;
        if (!std::isfinite(l.radius) || l.radius <= 0 || l.radius > maxRadius) {
            return invalidInput(at() + "radius: expected " +
                                (point ? std::string("a positive number (world units)")
                                       : "an angle in (0, 45] degrees") +
                                ", got " + number(l.radius));
        }
        if (!finite(l.color, 3) || l.color[0] < 0 || l.color[1] < 0 || l.color[2] < 0)
            return invalidInput(at() + "color: expected 3 finite numbers >= 0");
        if (!std::isfinite(l.intensity) || l.intensity < 0)
            return invalidInput(at() + "intensity: expected a finite number >= 0, got " +
                                number(l.intensity));
        if (l.preset < -1 || l.preset >= presetCount) {
            return invalidInput(at() + "preset: expected -1 or an id from fk_engine_load_preset (" +
                                (presetCount ? "0.." + std::to_string(presetCount - 1)
                                             : std::string("none loaded")) +
                                "), got " + std::to_string(l.preset));
        }
    }
    return Ok{};
}

void packLights(const fk_light* lights, int count, std::vector<float>& packed) {
    packed.assign(std::size_t(count) * 16, 0.f);
    for (int i = 0; i < count; ++i) {
        const fk_light& l = lights[i];
        float* p = packed.data() + std::size_t(i) * 16;
        const bool point = l.type == FK_LIGHT_POINT;
        std::memcpy(p, l.position, 3 * sizeof(float));
        p[3] = point ? 1.f : 0.f;
        std::memcpy(p + 4, l.direction, 3 * sizeof(float));
        // Directional radii arrive in degrees; the shaders take radians.
        p[7] = point ? l.radius : l.radius * 0.017453292519943295f;
        std::memcpy(p + 8, l.color, 3 * sizeof(float));
        p[11] = l.intensity;
        p[12] = float(l.preset);
    }
}

Status checkView(int view) {
    if (view >= 0 && view < FK_MAX_VIEWS) return Ok{};
    return invalidInput("view: expected 0.." + std::to_string(FK_MAX_VIEWS - 1) + ", got " +
                        std::to_string(view));
}

Status checkFramebuffer(unsigned framebuffer) {
    if (framebuffer == 0) return Ok{};
    if (!glIsFramebuffer(framebuffer)) {
        return invalidInput("framebuffer: expected 0 or the name of a GL framebuffer, got " +
                            std::to_string(framebuffer));
    }
    if (glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return invalidInput("framebuffer: expected a complete framebuffer");
    return Ok{};
}

}  // namespace flarekit::engine
