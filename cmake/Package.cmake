# The installable package: libflarekit.so (the C API over flarekit::gl, exporting only fk_*),
# its headers, flarekitConfig.cmake + version file and flarekit.pc.
include(CMakePackageConfigHelpers)
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
  flarekit_warnings)
target_link_options(flarekit PRIVATE -Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/flarekit.map
  -Wl,--no-undefined)
install(TARGETS flarekit EXPORT flarekitTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT flarekitTargets NAMESPACE flarekit:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flarekit)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/flarekitConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/flarekitConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flarekit)
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/flarekitConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/flarekitConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/flarekitConfigVersion.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/flarekit)
configure_file(${PROJECT_SOURCE_DIR}/cmake/flarekit.pc.in ${CMAKE_CURRENT_BINARY_DIR}/flarekit.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/flarekit.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
