# Installs the libraries and public headers so that an outside project can
# find_package(asperity) and link asperity::asperity, asperity::gl, asperity::render and
# asperity::bullet (examples/cpp/, built against an installed copy by the
# InstallAndBuildExamples test).
# Component `cpp`; the Python module installs as component `python` (python/CMakeLists.txt).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(asperity_installed_targets asperity)
foreach(optional asperity_gl asperity_render asperity_bullet)
  if(TARGET ${optional})
    list(APPEND asperity_installed_targets ${optional})
  endif()
endforeach()
install(TARGETS ${asperity_installed_targets} EXPORT asperityTargets COMPONENT cpp
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/asperity DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT cpp)
install(EXPORT asperityTargets NAMESPACE asperity:: FILE asperityTargets.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/asperity COMPONENT cpp)
# The config finds the GL dependencies only when the GL targets were built.
if(TARGET asperity_gl)
  set(ASPERITY_INSTALLED_GL ON)
else()
  set(ASPERITY_INSTALLED_GL OFF)
endif()
configure_package_config_file(cmake/asperityConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/asperityConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/asperity)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/asperityConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/asperityConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/asperityConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/asperity COMPONENT cpp)
