// Encoding-error values to colours, shared by `oasis render` and the window.
#include "debug/error_image.h"

#include <cmath>

#include "debug/view_legend.h"

namespace oasis {

Image encodingErrorPicture(const std::vector<float>& values, int width, int height, double low, double high) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float v = values[size_t(y) * size_t(width) + size_t(x)];
            uint8_t* out = image.pixel(x, height - 1 - y);
            if (std::isfinite(v)) depthRampColour(float((double(v) - low) / (high - low)), out);
            else out[0] = out[1] = out[2] = 40;
            out[3] = 255;
        }
    return image;
}

}  // namespace oasis
