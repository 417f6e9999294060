# static-libraries.cmake — CMAKE_USER_MAKE_RULES_OVERRIDE of the cross toolchain files
# here: read after CMake's platform files (which set the library suffixes, so a toolchain
# file cannot), it makes find_library() pick static archives (libm.a, not libm.so) for
# the -static links.
set(CMAKE_FIND_LIBRARY_SUFFIXES ".a")
