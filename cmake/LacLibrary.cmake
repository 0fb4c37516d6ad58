# The library `lac` (alias lac::lac): every .cpp under the library folders, one library, static by
# default and shared with -DBUILD_SHARED_LIBS=ON; position-independent either way, so that the
# static library links into the Python module (python/) as well.
#
# Headers are included as <lac/<folder>/<file>.hpp>, in the source tree as in an installed tree. The
# build tree gets an include folder with one symbolic link per library folder
# (<build>/include/lac/<folder> -> <source>/<folder>) and the generated lac/version.hpp. The public
# headers form the file set HEADERS of the target, installed under <prefix>/include/lac/<folder>/:
# every header outside a detail/ folder, and the detail/ headers that those include (templates
# and inline kernels). The other detail/ headers belong to the .cpp files and are not installed.
#
# Link dependencies: Boost and Eigen appear in the public headers (PUBLIC); Ceres and libcerf only
# in .cpp files (PRIVATE: a consumer of the shared library does not link them; a consumer of the
# static library links them through $<LINK_ONLY:...>, and lacConfig.cmake finds them then).
set(LAC_LIBRARY_FOLDERS common special integrators solvers curves geometry constructions export)

set(LAC_SOURCES "")
set(LAC_HEADERS "")
foreach(folder IN LISTS LAC_LIBRARY_FOLDERS)
  file(GLOB_RECURSE folder_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.cpp)
  file(GLOB_RECURSE folder_headers CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/${folder}/*.hpp)
  # export/occt/ is the optional OpenCASCADE component (cmake/LacExportOcct.cmake), not in lac.
  list(FILTER folder_sources EXCLUDE REGEX "/export/occt/")
  list(FILTER folder_headers EXCLUDE REGEX "^export/occt/")
  list(APPEND LAC_SOURCES ${folder_sources})
  list(APPEND LAC_HEADERS ${folder_headers})
endforeach()

# Public headers: the non-detail ones, then every header they include (transitively).
set(LAC_PUBLIC_HEADERS ${LAC_HEADERS})
list(FILTER LAC_PUBLIC_HEADERS EXCLUDE REGEX "/detail/")
set(lac_queue ${LAC_PUBLIC_HEADERS})
while(lac_queue)
  list(POP_FRONT lac_queue header)
  file(STRINGS ${PROJECT_SOURCE_DIR}/${header} lines REGEX "^#include \"lac/")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^#include \"lac/([^\"]+)\".*" "\\1" included "${line}")
    if(EXISTS ${PROJECT_SOURCE_DIR}/${included} AND NOT included IN_LIST LAC_PUBLIC_HEADERS)
      list(APPEND LAC_PUBLIC_HEADERS ${included})
      list(APPEND lac_queue ${included})
    endif()
  endforeach()
endwhile()
list(SORT LAC_PUBLIC_HEADERS)

set(LAC_BUILD_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)
file(MAKE_DIRECTORY ${LAC_BUILD_INCLUDE_DIR}/lac)
foreach(folder IN LISTS LAC_LIBRARY_FOLDERS)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${LAC_BUILD_INCLUDE_DIR}/lac/${folder} SYMBOLIC)
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in ${LAC_BUILD_INCLUDE_DIR}/lac/version.hpp @ONLY)
# The file set names each header by its path under the build include folder (through the links),
# so that it installs as include/lac/<folder>/<file>.hpp.
list(TRANSFORM LAC_PUBLIC_HEADERS PREPEND ${LAC_BUILD_INCLUDE_DIR}/lac/ OUTPUT_VARIABLE LAC_PUBLIC_HEADER_FILES)

add_library(lac ${LAC_SOURCES})
add_library(lac::lac ALIAS lac)
set_target_properties(lac PROPERTIES VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
                                     EXPORT_NAME lac POSITION_INDEPENDENT_CODE ON)
target_compile_features(lac PUBLIC cxx_std_20)
# PIC code may call its own global functions through the PLT and not inline them (ELF interposition);
# no part of lac is meant to be interposed, so keep the optimizations of the non-PIC build.
target_compile_options(lac PRIVATE $<$<CXX_COMPILER_ID:GNU,Clang>:-fno-semantic-interposition>)
# The G2 Bézier-grid screening (one loop over 10^4 candidates) vectorizes only where sqrt and
# division need not set errno, which no caller reads.
set_source_files_properties(constructions/detail/bezier_start.cpp PROPERTIES
  COMPILE_OPTIONS "$<$<CXX_COMPILER_ID:GNU,Clang>:-fno-math-errno>")
target_include_directories(lac PUBLIC $<BUILD_INTERFACE:${LAC_BUILD_INCLUDE_DIR}> $<INSTALL_INTERFACE:include>)
target_sources(lac PUBLIC FILE_SET HEADERS BASE_DIRS ${LAC_BUILD_INCLUDE_DIR}
               FILES ${LAC_PUBLIC_HEADER_FILES} ${LAC_BUILD_INCLUDE_DIR}/lac/version.hpp)
target_link_libraries(lac PUBLIC Boost::boost Eigen3::Eigen PRIVATE Ceres::ceres PkgConfig::CERF)
# glibc's vector math library (libmvec, x86-64): cos and sin of a quadrature panel's nodes two at a
# time (common/unit_phasors.cpp); without it the same function loops over std::cos/std::sin.
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  find_library(LAC_LIBMVEC NAMES mvec)
endif()
if(LAC_LIBMVEC)
  set_property(SOURCE common/unit_phasors.cpp APPEND PROPERTY COMPILE_DEFINITIONS LAC_HAVE_LIBMVEC)
  target_link_libraries(lac PRIVATE mvec)
endif()

if(LAC_INSTALL)
  include(GNUInstallDirs)
  include(CMakePackageConfigHelpers)
  install(TARGETS lac EXPORT lacTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
          FILE_SET HEADERS DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  set(LAC_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/lac)
  install(EXPORT lacTargets NAMESPACE lac:: DESTINATION ${LAC_CMAKE_DIR})
  get_target_property(LAC_TYPE lac TYPE)  # lacConfig.cmake looks up the private dependencies of a static lac
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lacConfig.cmake.in ${PROJECT_BINARY_DIR}/lacConfig.cmake
                                INSTALL_DESTINATION ${LAC_CMAKE_DIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/lacConfigVersion.cmake COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/lacConfig.cmake ${PROJECT_BINARY_DIR}/lacConfigVersion.cmake
          DESTINATION ${LAC_CMAKE_DIR})
endif()
