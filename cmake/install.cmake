# `cmake --install BUILD [--prefix P]`: P/bin/hbtrack, P/lib/libhbtrack.a, P/include/hbtrack/,
# the CMake package P/lib/cmake/hbtrack (find_package(hbtrack) -> hbtrack::hbtrack) and the
# Python package P/lib/pythonX.Y/site-packages/hbtrack (docs/install.md).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS hbtrack EXPORT hbtrackTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS hbtrack_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/hbtrack DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
install(EXPORT hbtrackTargets NAMESPACE hbtrack:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hbtrack)
configure_package_config_file(cmake/hbtrackConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/hbtrackConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hbtrack PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_BINDIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/hbtrackConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hbtrackConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/hbtrackConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hbtrack)

if(HBTRACK_PYTHON)
  set(HBTRACK_PYTHON_INSTALL_DIR "${CMAKE_INSTALL_LIBDIR}/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/site-packages"
      CACHE STRING "Where `cmake --install` puts the Python package hbtrack (relative to the prefix, or absolute)")
  install(TARGETS _hbtrack LIBRARY DESTINATION ${HBTRACK_PYTHON_INSTALL_DIR}/hbtrack)
  install(DIRECTORY python/hbtrack/ DESTINATION ${HBTRACK_PYTHON_INSTALL_DIR}/hbtrack
          FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
  install(FILES ${CMAKE_BINARY_DIR}/python/hbtrack/_built_for.txt DESTINATION ${HBTRACK_PYTHON_INSTALL_DIR}/hbtrack)
  # The installed tool finds this package from its own bin folder, so that a moved or copied
  # prefix keeps working (apps/hbtrack/python_package.cpp).
  if(IS_ABSOLUTE "${HBTRACK_PYTHON_INSTALL_DIR}")
    set(HBTRACK_PYTHON_FROM_BIN "${HBTRACK_PYTHON_INSTALL_DIR}")
  else()
    file(RELATIVE_PATH HBTRACK_PYTHON_FROM_BIN /prefix/${CMAKE_INSTALL_BINDIR} /prefix/${HBTRACK_PYTHON_INSTALL_DIR})
  endif()
endif()
set_property(SOURCE apps/hbtrack/python_package.cpp APPEND PROPERTY COMPILE_DEFINITIONS HBTRACK_PYTHON_FROM_BIN="${HBTRACK_PYTHON_FROM_BIN}")

if(HBTRACK_BUILD_TESTS AND NOT HBTRACK_SANITIZE)
  # Installs this build tree (no rebuild) into a temporary prefix, builds examples/consumer
  # against it with find_package(hbtrack) and runs it; imports the installed Python package.
  add_test(NAME install_and_consume
           COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                   -DPREFIX=${CMAKE_BINARY_DIR}/install_test "-DGENERATOR=${CMAKE_GENERATOR}"
                   -DCXX_COMPILER=${CMAKE_CXX_COMPILER} -DLAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
                   -DPYTHON=$<$<BOOL:${HBTRACK_PYTHON}>:${Python3_EXECUTABLE}>
                   -DPYTHON_DIR=$<$<BOOL:${HBTRACK_PYTHON}>:${HBTRACK_PYTHON_INSTALL_DIR}>
                   -P ${PROJECT_SOURCE_DIR}/tests/install_and_consume.cmake)
  set_tests_properties(install_and_consume PROPERTIES TIMEOUT 300)
endif()
