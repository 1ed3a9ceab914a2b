# SPDX-License-Identifier: Apache-2.0
# The installable package, one export set (flarekitTargets) of four targets:
#   flarekit::flarekit  libflarekit.so, the C API over flarekit::gl, exporting only fk_* (GL builds)
#   flarekit::core      libflarekit_core.a, the GL-free C++ library
#   flarekit::gl        libflarekit_gl.a, the OpenGL paths over core (GL builds)
#   flarekit::ocio      libflarekit_ocio.a, the jobs' colour transform over OpenColorIO
# with flarekitConfig.cmake (which finds the archives' own dependencies), its version file, and a
# pkg-config file for each.
include(CMakePackageConfigHelpers)
set(FLAREKIT_PC_FILES flarekit-core.pc flarekit-ocio.pc)
if(FLAREKIT_GL)
  add_library(flarekit SHARED ${PROJECT_SOURCE_DIR}/src/engine/SharedLibrary.cpp)
  add_library(flarekit::flarekit ALIAS flarekit)
  set_target_properties(flarekit PROPERTIES
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
    CXX_VISIBILITY_PRESET hidden LINK_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/flarekit.map)
  target_include_directories(flarekit INTERFACE
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # Every object of flarekit_gl, so the C API's entry points are in the library; flarekit_core's
  # objects come in as they are needed.
  target_link_libraries(flarekit PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,flarekit_gl>" flarekit_core
    $<BUILD_INTERFACE:flarekit_warnings>)
  target_link_options(flarekit PRIVATE -Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/flarekit.map
    -Wl,--no-undefined)
  install(TARGETS flarekit EXPORT flarekitTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  list(APPEND FLAREKIT_PC_FILES flarekit.pc flarekit-gl.pc)
endif()
install(EXPORT flarekitTargets NAMESPACE flarekit:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flarekit)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/flarekitConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/flarekitConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flarekit)
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/flarekitConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/flarekitConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/flarekitConfigVersion.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flarekit)
foreach(pc IN LISTS FLAREKIT_PC_FILES)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/${pc}.in ${CMAKE_CURRENT_BINARY_DIR}/${pc} @ONLY)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/${pc} DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()
