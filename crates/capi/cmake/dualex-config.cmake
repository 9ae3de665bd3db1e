# CMake package config of the dualex C API: defines the imported target
# dualex::dualex (header include/dualex.h, library libdualex_capi).
#
# Installed layout (see README, "Use from C/C++"):
#   <prefix>/include/dualex.h
#   <prefix>/lib/libdualex_capi.so  (and/or libdualex_capi.a)
#   <prefix>/lib/cmake/dualex/dualex-config.cmake   (this file)
# Use:
#   find_package(dualex REQUIRED)        # -Ddualex_DIR=<prefix>/lib/cmake/dualex
#   target_link_libraries(app PRIVATE dualex::dualex)
# Set DUALEX_STATIC=ON before find_package to link the static library.

get_filename_component(_dualex_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)

if(DUALEX_STATIC)
  set(_dualex_kind STATIC)
  set(_dualex_name "${CMAKE_STATIC_LIBRARY_PREFIX}dualex_capi${CMAKE_STATIC_LIBRARY_SUFFIX}")
else()
  set(_dualex_kind SHARED)
  set(_dualex_name "${CMAKE_SHARED_LIBRARY_PREFIX}dualex_capi${CMAKE_SHARED_LIBRARY_SUFFIX}")
endif()

set(_dualex_lib "${_dualex_prefix}/lib/${_dualex_name}")
if(NOT EXISTS "${_dualex_lib}" OR NOT EXISTS "${_dualex_prefix}/include/dualex.h")
  set(dualex_FOUND FALSE)
  set(dualex_NOT_FOUND_MESSAGE "dualex: ${_dualex_lib} or ${_dualex_prefix}/include/dualex.h is missing")
  return()
endif()

if(NOT TARGET dualex::dualex)
  add_library(dualex::dualex ${_dualex_kind} IMPORTED)
  set_target_properties(dualex::dualex PROPERTIES
    IMPORTED_LOCATION "${_dualex_lib}"
    INTERFACE_INCLUDE_DIRECTORIES "${_dualex_prefix}/include")
  if(DUALEX_STATIC AND UNIX)
    # what Rust's standard library needs (rustc --print native-static-libs)
    find_package(Threads REQUIRED)
    set_property(TARGET dualex::dualex PROPERTY
      INTERFACE_LINK_LIBRARIES Threads::Threads ${CMAKE_DL_LIBS} m)
  endif()
endif()

set(dualex_VERSION 0.1.0)
set(dualex_FOUND TRUE)
