// The shading oracle's CPU twin of oasis's surface shading: shadeSurface (shaders/common/lighting.glsl)
// and the point lights (common/lights.glsl), evaluated in double precision from a surface, the
// frame's constants, the sun's visibility (check/oracle_shadow.h) and the light list. Each term
// carries the shading probe's name (frame/shading_probe.cpp), so a difference can be named.
// Keep it in step with the GLSL: the check's oracle fails wherever the two part.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_data.h"
#include "render/light_data.h"

namespace oasis {

// GLSL's smoothstep, in double (the shadow fade and the terrain's grid fade use it).
inline double smoothstepOf(double edge0, double edge1, double x) {
    double t = (x - edge0) / (edge1 - edge0);
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return t * t * (3.0 - 2.0 * t);
}

// A surface as readGBuffer() returns it (common/surface.glsl's Surface).
struct OracleSurface {
    glm::dvec3 albedo{0.0};
    glm::dvec3 normal{0.0, 1.0, 0.0};     // as stored: shadeSurface normalises it
    glm::dvec3 relativePosition{0.0};     // camera-relative, the mirror image where REFLECTED
    double specularPower = 1.0;
    double specularIntensity = 0.0;
    unsigned flags = 0;
};

// shadeSurface's terms, in the order it computes them.
struct SurfaceTerms {
    glm::dvec3 toSun{0.0}, sunRadiance{0.0}, toCamera{0.0}, normal{0.0};
    double nDotL = 0.0;                // unclamped
    double shadow = 1.0;               // the sun's visibility, as given
    int cascade = -1;                  // the cascade that gave it (-1 none)
    glm::dvec3 sunAtSurface{0.0};
    double diffuse = 0.0, normalisation = 0.0, nDotH = 0.0, specular = 0.0;
    glm::dvec3 ambient{0.0}, albedo{0.0};
    double specularPower = 0.0;
    glm::dvec3 diffusePart{0.0}, ambientPart{0.0}, specularPart{0.0}, lit{0.0};
    glm::dvec3 waterCrossed{1.0};
    double underLength = 0.0;
    bool reflected = false;
    glm::dvec3 waterScatter{0.0}, afterWater{0.0};
    double fog = 0.0, eyeDistance = 0.0;
    glm::dvec3 fogColour{0.0}, surface{0.0};
};

// Where the surface really is, camera-relative (a reflection's stored position is mirrored).
glm::dvec3 oracleLitPosition(const FrameData& frame, const OracleSurface& s);
// shadeSurface with the sun's visibility `shadow` from `cascade` (sunShadow(), check/oracle_shadow.h).
SurfaceTerms oracleShadeSurface(const FrameData& frame, const OracleSurface& s, double shadow, int cascade);

// The point lights: the windowed inverse-square falloff, one light's radiance at the surface
// before the eye (pointLightRadiance), and what carries it to the eye (pointLightTransfer).
double oraclePointLightFalloff(double distanceToLight, double radius);
glm::dvec3 oraclePointLightRadiance(const FrameData& frame, const OracleSurface& s, const PointLight& light);
glm::dvec3 oraclePointLightTransfer(const FrameData& frame, const OracleSurface& s);

// One light's share at the eye, by its index in the list (only the lights that reach the surface).
struct LightShare {
    int index = 0;
    glm::dvec3 radiance{0.0};
};
struct PixelShading {
    SurfaceTerms surface;
    std::vector<LightShare> lights;  // in list order
    glm::dvec3 lightsSum{0.0};       // every share summed, carried to the eye
    glm::dvec3 radiance{0.0};        // surface + lights: what Radiance holds
};
PixelShading oracleShadePixel(const FrameData& frame, const OracleSurface& s, double shadow, int cascade,
                              const std::vector<PointLight>& lights);

// A term as the shading probe names it, with the values it records (common/shading_terms.glsl).
struct NamedTerm {
    std::string name;
    std::vector<double> values;
};
// The pixel's terms in the probe's order: the surface terms, "lights", each "light N", "radiance".
std::vector<NamedTerm> oracleNamedTerms(const PixelShading& shading);

}  // namespace oasis
