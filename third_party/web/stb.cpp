// What Debian's libstb provides to the desktop build, for the browser build: the PNG and JPEG
// reader and the PNG writer, compiled from Debian's headers.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
