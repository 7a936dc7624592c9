# libnavlink.a: the objects libnavlink.so is linked from, joined into one relocatable object (`ld -r`) in
# which every hidden symbol is made local (`objcopy --localize-hidden`). An archive of the plain objects
# would hand the host's link every internal C++ symbol of the core and of what it compiles in
# (tinyobjloader's implementation, for one), free to clash with the host's own copies; this way, as from
# libnavlink.so, only the NL_API functions (nl_*) leave it: the version script's job in the shared build.
# Needs GNU ld and binutils' objcopy (docs/platforms.md).
#
# A static build (NAVLINK_SHARED=OFF) makes it its `navlink`. A shared build makes it `navlink_static`,
# installed beside libnavlink.so as a -dev package ships both: the objects are the ones the .so is
# linked from, already compiled and position-independent (a host can link the archive into a shared
# library of its own, an engine's native plugin), so the archive costs one link, not a second compile.
if(NOT CMAKE_OBJCOPY OR NOT CMAKE_LINKER)
  message(FATAL_ERROR "libnavlink.a needs a linker that can do `ld -r` and binutils' objcopy "
                      "(CMAKE_LINKER='${CMAKE_LINKER}', CMAKE_OBJCOPY='${CMAKE_OBJCOPY}')")
endif()
if(NAVLINK_SHARED)
  set(NAVLINK_STATIC_TARGET navlink_static)
else()
  set(NAVLINK_STATIC_TARGET navlink)
endif()

set(_navlink_joined ${CMAKE_CURRENT_BINARY_DIR}/navlink_joined.o)
set(_navlink_archives $<TARGET_FILE:navlink_builtin_plugins> $<TARGET_FILE:navlink_recast_plugin>
                      $<TARGET_FILE:navlink_core>)
# Archive members are taken as `ld -r` needs them, as in the shared link: what the C ABI reaches.
add_custom_command(OUTPUT ${_navlink_joined}
  COMMAND ${CMAKE_LINKER} -r -o ${_navlink_joined} $<TARGET_OBJECTS:navlink_capi_objects>
          --start-group ${_navlink_archives} --end-group
  COMMAND ${CMAKE_OBJCOPY} --localize-hidden ${_navlink_joined}
  DEPENDS navlink_capi_objects $<TARGET_OBJECTS:navlink_capi_objects> navlink_builtin_plugins navlink_recast_plugin
          navlink_core
  COMMENT "Joining libnavlink's objects, only nl_* global"
  COMMAND_EXPAND_LISTS VERBATIM)

find_package(Threads REQUIRED)  # its imported target is local to the folder that found it (sdk/)
# The cache entry plugins/recast/ finds too: capi/ is configured before plugins/, so on a first
# configure it would still be empty here.
find_library(NAVLINK_RECAST_LIBRARY Recast REQUIRED)
add_library(${NAVLINK_STATIC_TARGET} STATIC ${_navlink_joined} src/static_library_language.cpp)
set_target_properties(${NAVLINK_STATIC_TARGET} PROPERTIES OUTPUT_NAME navlink)
if(NAVLINK_SHARED AND NOT NAVLINK_INSTALL)
  # Made for the install: a project that builds NavLink inside its own makes it only if it links it.
  set_target_properties(${NAVLINK_STATIC_TARGET} PROPERTIES EXCLUDE_FROM_ALL ON)
endif()
# NL_API without dllimport (export.h): for Windows; elsewhere it changes nothing.
target_compile_definitions(${NAVLINK_STATIC_TARGET} INTERFACE NL_STATIC)
# What the joined object still needs at link time: the core's and the Recast builder's libraries
# (sdk/CMakeLists.txt, plugins/recast/CMakeLists.txt), the loader of plugin modules, and the C++
# runtime (src/static_library_language.cpp). Exported as link-only dependencies, found again by NavLinkConfig.
target_link_libraries(${NAVLINK_STATIC_TARGET} PRIVATE embree TBB::tbb ZLIB::ZLIB Threads::Threads
                      ${NAVLINK_RECAST_LIBRARY} ${NAVLINK_DETOUR_CROWD_LIBRARY} ${NAVLINK_DETOUR_LIBRARY}
                      ${CMAKE_DL_LIBS})

# The same for consumers outside CMake (navlink.pc or navlink-static.pc, `pkg-config --static`) and for
# NavLinkConfig.cmake.
set(NAVLINK_PC_STATIC_CFLAGS " -DNL_STATIC")
set(NAVLINK_PC_STATIC_REQUIRES_PRIVATE "Requires.private: tbb zlib\n")
set(_navlink_libs_private -lembree${embree_VERSION_MAJOR})
foreach(_library IN ITEMS ${NAVLINK_RECAST_LIBRARY} ${NAVLINK_DETOUR_CROWD_LIBRARY} ${NAVLINK_DETOUR_LIBRARY})
  get_filename_component(_name ${_library} NAME_WE)
  string(REGEX REPLACE "^lib" "" _name ${_name})
  list(APPEND _navlink_libs_private -l${_name})
endforeach()
foreach(_library IN ITEMS ${CMAKE_DL_LIBS})
  list(APPEND _navlink_libs_private -l${_library})
endforeach()
list(APPEND _navlink_libs_private ${CMAKE_THREAD_LIBS_INIT} -lstdc++ -lm)
list(JOIN _navlink_libs_private " " _navlink_libs_private)
set(NAVLINK_PC_STATIC_LIBS_PRIVATE "Libs.private: ${_navlink_libs_private}\n")
set(NAVLINK_CONFIG_STATIC_DEPENDENCIES [[
include(CMakeFindDependencyMacro)
find_dependency(embree 3 CONFIG)
find_dependency(TBB CONFIG)
find_dependency(ZLIB)
find_dependency(Threads)
# The library is C++ inside: CMake links its consumers with the C++ driver, which needs CXX enabled.
get_property(_navlink_languages GLOBAL PROPERTY ENABLED_LANGUAGES)
if(NOT "CXX" IN_LIST _navlink_languages)
  set(${CMAKE_FIND_PACKAGE_NAME}_FOUND FALSE)
  string(CONCAT ${CMAKE_FIND_PACKAGE_NAME}_NOT_FOUND_MESSAGE
         "NavLink's libnavlink.a is C++ inside: enable CXX in your project "
         "(project(... LANGUAGES C CXX)) so that its programs link with the C++ runtime")
  return()
endif()
]])
