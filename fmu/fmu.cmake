# The FMU binary (fmu/src, C11): the FMI 2.0 Co-Simulation functions on
# libhydrocoef_runtime's objects, linked in statically, so that the binary
# needs libc and libm only; it exports the fmi2* functions alone
# (hydrocoef_fmu.map). Its bytes are embedded into the library
# (fmu/embed_binary.cmake -> generated/fmu_binary.cpp) for `hydrocoef
# export-fmu` to copy into binaries/linux64/<modelIdentifier>.so. Included
# from the top CMakeLists.txt (the generated source belongs to
# hydrocoef_objects, defined there). In the sanitizer build the binary
# carries the sanitizers' instrumentation, as the runtime library does, and
# loads into sanitized hosts only.
file(GLOB HYDROCOEF_FMU_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/src/*.c)
add_library(hydrocoef_fmu MODULE ${HYDROCOEF_FMU_SOURCES} $<TARGET_OBJECTS:hydrocoef_runtime_objects>)
set_target_properties(hydrocoef_fmu PROPERTIES PREFIX "" C_STANDARD 11 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF
  C_VISIBILITY_PRESET hidden LINK_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/hydrocoef_fmu.map)
target_include_directories(hydrocoef_fmu PRIVATE ${CMAKE_CURRENT_LIST_DIR}/include
  ${PROJECT_SOURCE_DIR}/runtime/include ${PROJECT_SOURCE_DIR})
target_compile_options(hydrocoef_fmu PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  -Werror -fno-math-errno -fno-trapping-math)
target_link_options(hydrocoef_fmu PRIVATE "LINKER:--version-script=${CMAKE_CURRENT_LIST_DIR}/hydrocoef_fmu.map"
  "LINKER:--as-needed")
if(NOT HYDROCOEF_SANITIZE)
  target_link_options(hydrocoef_fmu PRIVATE "LINKER:--no-undefined")
endif()
target_link_libraries(hydrocoef_fmu PRIVATE m)

set(HYDROCOEF_FMU_BINARY_SOURCE ${PROJECT_BINARY_DIR}/generated/fmu_binary.cpp)
add_custom_command(OUTPUT ${HYDROCOEF_FMU_BINARY_SOURCE}
  COMMAND ${CMAKE_COMMAND} -DINPUT=$<TARGET_FILE:hydrocoef_fmu> -DOUTPUT=${HYDROCOEF_FMU_BINARY_SOURCE}
          -P ${CMAKE_CURRENT_LIST_DIR}/embed_binary.cmake
  DEPENDS hydrocoef_fmu ${CMAKE_CURRENT_LIST_DIR}/embed_binary.cmake
  COMMENT "Embedding the FMU binary" VERBATIM)
target_sources(hydrocoef_objects PRIVATE ${HYDROCOEF_FMU_BINARY_SOURCE})
