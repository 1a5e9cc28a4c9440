// The depth conventions: the one table of how the frame's depth is stored, cleared, compared and
// projected. `--depth NAME` picks a row; every pass takes its depth state from the row its targets
// were made with (FrameTargets::depth()), and the camera projects with the row's mapping.
#pragma once
#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "render/gbuffer_layout.h"
#include "scene/camera.h"

namespace oasis {

struct DepthConvention {
    std::string name;
    std::string description;
    DepthMapping mapping;            // how the camera's projection maps distance to NDC z
    TargetFormat depthStencil;       // the shared depth-stencil target; bytes as drivers allocate them
    GLenum nearerFunc;               // passes when the fragment is in front of what is stored
    GLenum nearerOrEqualFunc;        // also passes at the same depth: draws at the far plane over the clear
    GLenum fartherFunc;              // passes behind what is stored: a far-plane draw over surfaces only
    GLenum clipOrigin, clipDepthMode;  // glClipControl for the frame
    float nearPlaneNdcZ;             // NDC z of the near plane
    float farPlaneNdcZ;              // NDC z of the far plane: full-screen draws there (the sky)
    float farPlaneWindowDepth;       // window depth of the far plane: the depth clear value

    bool reversed() const { return mapping == DepthMapping::Reversed; }
    // Whether the frame needs glClipControl (GL 4.5 or GL_ARB_clip_control): not OpenGL's default.
    bool needsClipControl() const { return clipDepthMode != GL_NEGATIVE_ONE_TO_ONE || clipOrigin != GL_LOWER_LEFT; }
    // FrameData.depthConvention (shaders/common/frame_data.glsl).
    glm::vec4 frameData() const {
        return glm::vec4(reversed() ? 1.0f : 0.0f, nearPlaneNdcZ, farPlaneWindowDepth, farPlaneNdcZ);
    }
};

const std::vector<DepthConvention>& depthConventions();
const DepthConvention* findDepthConvention(const std::string& name);
const DepthConvention& standardDepthConvention();  // the default, and the fallback without clip control
std::string depthConventionNames();                // "standard, reversed-z" for help and error text

// How far along its view ray one step of the stored depth moves a point at eye distance d: D24's
// 1/(2^24-1) of window depth is d^2 (f-n) / (f n (2^24-1)); reversed-z's float keeps about 2^-24 of
// d. The unit of the encoding-error views' and the probe's "depth steps".
double depthStepAt(const DepthConvention& depth, double eyeDistance, double nearPlane, double farPlane);

// The format of any frame target: the depth-stencil from the convention, the rest from the layout.
TargetFormat targetFormat(const GBufferLayout& layout, const DepthConvention& depth, Target target);
// The G-buffer's bytes per pixel (four colour targets plus depth-stencil) with this convention's depth.
int gbufferBytesPerPixel(const GBufferLayout& layout, const DepthConvention& depth);

// Sets the convention's clip control for the draws of a frame and puts OpenGL's default back when
// it ends, so nothing drawn outside a frame (the window's panel, the plant atlas, other tests) sees
// it. A convention that needs none makes no GL call (contexts without glClipControl).
class FrameClipControl {
public:
    explicit FrameClipControl(const DepthConvention& depth);
    ~FrameClipControl();
    FrameClipControl(const FrameClipControl&) = delete;
    FrameClipControl& operator=(const FrameClipControl&) = delete;

private:
    bool set_ = false;
};

}  // namespace oasis
