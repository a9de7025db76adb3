# What `cmake --install` puts under the prefix for libhydrocoef_runtime (included from CMakeLists.txt after
# cmake/install.cmake, which sets LIBDIR): LIBDIR/libhydrocoef_runtime.so.1 (.so, .a) and
# include/hydrocoef/runtime.h (and runtime_frames.h and the C++ wrapper runtime.hpp, header only). A C consumer needs nothing else: -lhydrocoef_runtime, or the .a and -lm.
install(TARGETS hydrocoef_runtime_shared LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS hydrocoef_runtime ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES ${CMAKE_CURRENT_LIST_DIR}/include/hydrocoef/runtime.h
              ${CMAKE_CURRENT_LIST_DIR}/include/hydrocoef/runtime_frames.h
              ${CMAKE_CURRENT_LIST_DIR}/include/hydrocoef/runtime.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hydrocoef)
