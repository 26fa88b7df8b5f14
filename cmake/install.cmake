# `cmake --install`: the libraries (foresight::<folder>), their public headers under
# include/foresight/<folder>/, the `foresight` command, the shipped data under
# share/foresight/models and the package configuration for find_package(foresight CONFIG); and
# `cpack -G DEB` (make deb): foresight_<version>_amd64.deb with its Debian dependencies.
include(CMakePackageConfigHelpers)
# What is installed is the libraries and the command; installing (and cpack) needs only those
# built, not the tests and benchmarks.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(foresight_libraries common models stats report planner physics validation experiments cbr
  match)
foreach(lib IN LISTS foresight_libraries)
  set_target_properties(foresight_${lib} PROPERTIES EXPORT_NAME ${lib})
  install(TARGETS foresight_${lib} EXPORT foresightTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  # Every header of the folder is public: one folder = one library (docs/ARCHITECTURE.md).
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${lib}/ DESTINATION ${FORESIGHT_INSTALL_INCLUDE_DIR}/${lib}
    FILES_MATCHING PATTERN "*.h")
endforeach()
install(TARGETS foresight RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The executable of every command but `decide` (app/front_main.cc), where `foresight` finds it.
install(TARGETS foresight_full RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR})
# The Python package where Debian's python3 finds it (PREFIX/lib/python3/dist-packages/foresight).
if(TARGET foresight_python)
  install(TARGETS foresight_python LIBRARY DESTINATION ${FORESIGHT_INSTALL_PYTHON_DIR})
  install(FILES ${FORESIGHT_PYTHON_PACKAGE_FILES} DESTINATION ${FORESIGHT_INSTALL_PYTHON_DIR})
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/models/ DESTINATION ${FORESIGHT_INSTALL_MODELS_DIR}
  PATTERN "*.h" EXCLUDE PATTERN "*.cc" EXCLUDE PATTERN "CMakeLists.txt" EXCLUDE)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/foresight)
install(EXPORT foresightTargets NAMESPACE foresight:: DESTINATION ${config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/foresightConfig.cmake.in
  ${PROJECT_BINARY_DIR}/foresightConfig.cmake INSTALL_DESTINATION ${config_dir}
  PATH_VARS FORESIGHT_INSTALL_MODELS_DIR FORESIGHT_INSTALL_INCLUDE_DIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/foresightConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/foresightConfig.cmake
  ${PROJECT_BINARY_DIR}/foresightConfigVersion.cmake DESTINATION ${config_dir})

# The Debian package. Build it with the prefix it installs to (make deb: /usr), so that programs
# linked against the installed libraries find the data there (models/model_paths.h).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME foresight)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Robot-soccer kick selection by forward simulation, checked against Bullet physics")
set(CPACK_PACKAGE_CONTACT "foresight developers <foresight@localhost>")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # foresight_<version>_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The shared libraries the command links (libbullet, liburdfdom, libassimp, libstdc++, ...)
# from dpkg-shlibdeps; the development packages because the libraries are static archives whose
# public headers include Eigen and nlohmann::json and whose private dependencies a consumer links.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "libeigen3-dev, nlohmann-json3-dev, libbullet-dev, liburdfdom-dev, libassimp-dev, pkg-config")
# The Python module needs NumPy for simulate's arrays.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-numpy")
include(CPack)
