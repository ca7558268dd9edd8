# Compiler settings every Penumbra target shares.

if(PENUMBRA_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
                      -fno-sanitize=vptr) # Debian's glslang has no RTTI for the vptr check
  add_link_options(-fsanitize=address,undefined)
  # A sanitized static library needs the sanitizer runtime in whatever links it, the installed package's users too.
  set(PENUMBRA_CONSUMER_LINK_OPTIONS -fsanitize=address,undefined)
endif()
if(PENUMBRA_TSAN)
  if(PENUMBRA_SANITIZE)
    message(FATAL_ERROR "PENUMBRA_TSAN and PENUMBRA_SANITIZE exclude each other (ThreadSanitizer cannot run with ASan)")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
  set(PENUMBRA_CONSUMER_LINK_OPTIONS -fsanitize=thread)
endif()
# libFuzzer build (clang only, `make fuzz`): every library instrumented for coverage and sanitized; the fuzz
# targets in tests/fuzz link libFuzzer's main.
if(PENUMBRA_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PENUMBRA_FUZZ needs clang (libFuzzer): configure with CC=clang CXX=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined -fno-sanitize=vptr)
  add_link_options(-fsanitize=address,undefined)
endif()

# Designated initializers that leave fields at their documented defaults are the intended
# style of the descriptor structs, so GCC 12's missing-field-initializers warning is off.
function(penumbra_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wno-missing-field-initializers
                                           $<$<BOOL:${PENUMBRA_WERROR}>:-Werror>
                                           # In a batch only the first file is the main file, so GCC takes a type
                                           # of a later file's anonymous namespace for one declared in a header.
                                           $<$<BOOL:$<TARGET_PROPERTY:UNITY_BUILD>>:-Wno-subobject-linkage>)
endfunction()

# The headers only the backends share (rhi/backend/: checks every API must apply alike, the debug
# message log), on `target`'s own include path: never installed or exported, so no part of the public API.
function(penumbra_uses_backend_headers target)
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/rhi/backend)
endfunction()

# penumbra_library(<name> SOURCES ... ) -> target penumbra_<name>, alias penumbra::<name>,
# public headers in <dir>/include.
function(penumbra_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  add_library(penumbra_${name} ${ARG_SOURCES})
  add_library(penumbra::${name} ALIAS penumbra_${name})
  set_target_properties(penumbra_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME penumbra_${name})
  target_link_options(penumbra_${name} INTERFACE ${PENUMBRA_CONSUMER_LINK_OPTIONS})
  target_include_directories(penumbra_${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                                     $<INSTALL_INTERFACE:include>)
  penumbra_warnings(penumbra_${name})
  set_property(GLOBAL APPEND PROPERTY PENUMBRA_INSTALLED_TARGETS penumbra_${name})
  install(DIRECTORY include/ DESTINATION include)
endfunction()
