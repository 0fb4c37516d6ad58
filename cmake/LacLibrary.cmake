# The library `lac` (alias lac::lac): every .cpp under the library folders, one static library.
#
# Headers are included as <lac/<folder>/<file>.hpp>, in the source tree as in an installed tree. The
# build tree gets an include folder with one symbolic link per library folder
# (<build>/include/lac/<folder> -> <source>/<folder>) and the generated lac/version.hpp; the install
# rules copy the same headers to <prefix>/include/lac/<folder>/.
set(LAC_LIBRARY_FOLDERS common special integrators solvers curves constructions)

set(LAC_SOURCES "")
foreach(folder IN LISTS LAC_LIBRARY_FOLDERS)
  file(GLOB_RECURSE folder_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.cpp)
  list(APPEND LAC_SOURCES ${folder_sources})
endforeach()

set(LAC_BUILD_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${LAC_BUILD_INCLUDE_DIR}/lac)
foreach(folder IN LISTS LAC_LIBRARY_FOLDERS)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${LAC_BUILD_INCLUDE_DIR}/lac/${folder} SYMBOLIC)
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in ${LAC_BUILD_INCLUDE_DIR}/lac/version.hpp @ONLY)

add_library(lac STATIC ${LAC_SOURCES})
add_library(lac::lac ALIAS lac)
set_target_properties(lac PROPERTIES VERSION ${PROJECT_VERSION} EXPORT_NAME lac)
target_compile_features(lac PUBLIC cxx_std_20)
target_include_directories(lac PUBLIC $<BUILD_INTERFACE:${LAC_BUILD_INCLUDE_DIR}> $<INSTALL_INTERFACE:include>)
target_link_libraries(lac PUBLIC Boost::boost Eigen3::Eigen Ceres::ceres PkgConfig::CERF)

if(LAC_INSTALL)
  include(GNUInstallDirs)
  include(CMakePackageConfigHelpers)
  foreach(folder IN LISTS LAC_LIBRARY_FOLDERS)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lac/${folder}
            FILES_MATCHING PATTERN "*.hpp")
  endforeach()
  install(FILES ${LAC_BUILD_INCLUDE_DIR}/lac/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lac)
  install(TARGETS lac EXPORT lacTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  set(LAC_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/lac)
  install(EXPORT lacTargets NAMESPACE lac:: DESTINATION ${LAC_CMAKE_DIR})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lacConfig.cmake.in ${PROJECT_BINARY_DIR}/lacConfig.cmake
                                INSTALL_DESTINATION ${LAC_CMAKE_DIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/lacConfigVersion.cmake COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/lacConfig.cmake ${PROJECT_BINARY_DIR}/lacConfigVersion.cmake
          DESTINATION ${LAC_CMAKE_DIR})
endif()
