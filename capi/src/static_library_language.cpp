// Deliberately empty. libnavlink.a is one joined object (capi/static_library.cmake) that CMake cannot
// see into; this C++ source among its sources tells CMake the archive is C++, so that every program
// linking it, in this build or through the exported NavLink::navlink, is linked by the C++ driver
// with the C++ runtime.
