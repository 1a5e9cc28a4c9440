// stb_image and stb_image_write for the web build: natively they come from Debian's libstb; here
// their implementations are compiled from Debian's headers (libstb-dev), not copied.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
