# How NavLink's own targets are installed: the library (capi/), the programs (samples/) and the plugin
# modules (plugins/) each call one of these, so stripping and finding libnavlink are decided here once.

# The plugin modules' folder: nl_plugin_load takes a path, so hosts find them here by convention.
set(NAVLINK_INSTALL_PLUGINDIR ${CMAKE_INSTALL_LIBDIR}/navlink/plugins)

# navlink_strip_installed(<target> <destination>): strips the installed file of <target> in
# <destination> when NAVLINK_INSTALL_STRIPPED is ON. A RelWithDebInfo libnavlink.so is some 39 MB
# with its debug info and under 1 MB without: a plain `cmake --install` should give what ships, and
# the build tree keeps the debug info for debugging. `cmake --install --strip` does the same for
# every install; this makes it the default.
function(navlink_strip_installed target destination)
  if(NOT CMAKE_STRIP OR APPLE OR WIN32)  # GNU binutils' strip only
    return()
  endif()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "STATIC_LIBRARY")
    set(what --strip-debug)  # the archive's symbols are what its consumers link against
  else()
    set(what --strip-unneeded)  # keeps the dynamic symbols, drops the rest and the debug info
  endif()
  set(file "\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${destination}/$<TARGET_FILE_NAME:${target}>")
  set(strip "execute_process(COMMAND \"${CMAKE_STRIP}\" ${what} \"${file}\" COMMAND_ERROR_IS_FATAL ANY)")
  if(NAVLINK_INSTALL_STRIPPED)
    install(CODE "${strip}")
  elseif(type STREQUAL "STATIC_LIBRARY")
    # CMake's own stripping (`--strip`, and CPack's, which packages stripped) passes archives over, as a
    # full strip would drop the symbols they are linked by: their debug info goes then too.
    install(CODE "if(CMAKE_INSTALL_DO_STRIP)\n  ${strip}\nendif()")
  endif()
endfunction()

# navlink_install_program(<target>): installs a program into bin/, finding libnavlink.so in the
# prefix's library folder wherever the prefix is (`cmake --install --prefix`, a .deb).
function(navlink_install_program target)
  if(NOT NAVLINK_INSTALL)
    return()
  endif()
  file(RELATIVE_PATH bin_to_lib /${CMAKE_INSTALL_BINDIR} /${CMAKE_INSTALL_LIBDIR})
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/${bin_to_lib}")
  install(TARGETS ${target} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  navlink_strip_installed(${target} ${CMAKE_INSTALL_BINDIR})
endfunction()

# navlink_install_plugin(<target>): installs a plugin module (loaded with nl_plugin_load).
function(navlink_install_plugin target)
  if(NOT NAVLINK_INSTALL)
    return()
  endif()
  install(TARGETS ${target} LIBRARY DESTINATION ${NAVLINK_INSTALL_PLUGINDIR})
  navlink_strip_installed(${target} ${NAVLINK_INSTALL_PLUGINDIR})
endfunction()
