# Installs the libraries and exports them so that find_package(Penumbra) gives penumbra::<name>.
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

get_property(targets GLOBAL PROPERTY PENUMBRA_INSTALLED_TARGETS)
install(TARGETS ${targets} EXPORT PenumbraTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT PenumbraTargets NAMESPACE penumbra:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Penumbra)
# The same package in the build folder, so that an outside project can use a build without installing it.
export(EXPORT PenumbraTargets NAMESPACE penumbra:: FILE ${CMAKE_CURRENT_BINARY_DIR}/PenumbraTargets.cmake)
configure_package_config_file(cmake/PenumbraConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/PenumbraConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Penumbra)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/PenumbraConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/PenumbraConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/PenumbraConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Penumbra)
