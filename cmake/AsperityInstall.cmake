# Installs the core library so that an outside project can find_package(asperity).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
install(TARGETS asperity EXPORT asperityTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/asperity DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT asperityTargets NAMESPACE asperity:: FILE asperityTargets.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/asperity)
configure_package_config_file(cmake/asperityConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/asperityConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/asperity)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/asperityConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/asperityConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/asperityConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/asperity)
