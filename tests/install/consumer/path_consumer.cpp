// The path consumer compiled as C++: navlink.h is used from C++ hosts as often as from C, and a
// static libnavlink.a must link into a C++ program as well as into a C one.
#include "path_consumer.c"
