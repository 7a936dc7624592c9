// tinyobjloader's implementation, compiled from Debian's header into the library instead of linked
// from libtinyobjloader.so: a sanitizer or fuzz build then instruments it like our own code, so what
// it does with its input is checked too (the shared library is built without any sanitizer).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
