// The picture of an encoding-error view (frame/encoding_error.h): each pixel's error on the
// depth view's ramp from `low` to `high`, dark grey where the two frames share no surface. The
// render command adds its legend strip; the window shows it as the frame.
#pragma once
#include <vector>

#include "render/image.h"

namespace oasis {

// `values`: one float per pixel, bottom row first (GL order); the image is top row first.
Image encodingErrorPicture(const std::vector<float>& values, int width, int height, double low, double high);

}  // namespace oasis
