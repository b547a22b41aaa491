# `cmake --install build --prefix P`: the denoiser, the HAL and its Vulkan backend as the CMake
# package `asvgf` (find_package(asvgf CONFIG) gives asvgf::denoiser, asvgf::hal and
# asvgf::hal_vulkan), headers under P/include (asvgf/ is the denoiser's public API; its internal
# headers are not installed). The shaders are compiled into libdenoiser.a.
include(CMakePackageConfigHelpers)

set(ASVGF_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/asvgf)
install(TARGETS denoiser hal hal_vulkan EXPORT asvgfTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/hal/include/ ${CMAKE_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# presenter.hpp belongs to hal_vulkan_present (GLFW windows), which is not installed.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/hal_vulkan/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        PATTERN presenter.hpp EXCLUDE)
install(EXPORT asvgfTargets NAMESPACE asvgf:: DESTINATION ${ASVGF_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_SOURCE_DIR}/tools/cmake/asvgfConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/package/asvgfConfig.cmake INSTALL_DESTINATION ${ASVGF_INSTALL_CMAKEDIR})
# Until 1.0 a minor version may change the API: only the same minor version is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/package/asvgfConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/package/asvgfConfig.cmake ${CMAKE_BINARY_DIR}/package/asvgfConfigVersion.cmake
        DESTINATION ${ASVGF_INSTALL_CMAKEDIR})
