# cmake -DREADME=... -DOUT=... -DCC=... -DCFLAGS=... -DINCLUDE=... -DLIB=... -P pogonReadmeExample.cmake
# (CFLAGS: the build's flags, e.g. the sanitizers the library was compiled with)
# Compiles and runs the README's C example (its first ```c block) against the built
# library, so the front door's code is code that works.
file(READ "${README}" text)
string(FIND "${text}" "```c\n" start)
if(start EQUAL -1)
  message(FATAL_ERROR "docs_readme_example: README.md has no ```c block")
endif()
math(EXPR start "${start} + 5")
string(SUBSTRING "${text}" ${start} -1 rest)
string(FIND "${rest}" "```" stop)
string(SUBSTRING "${rest}" 0 ${stop} code)
file(MAKE_DIRECTORY "${OUT}")
file(WRITE "${OUT}/readme_example.c" "${code}")
separate_arguments(cflags UNIX_COMMAND "${CFLAGS}")
execute_process(COMMAND "${CC}" ${cflags} -std=c99 -Wall -Wextra -Werror -I "${INCLUDE}" "${OUT}/readme_example.c" "${LIB}"
                        -o "${OUT}/readme_example"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "docs_readme_example: the README's example does not compile:\n${out}${err}")
endif()
execute_process(COMMAND "${OUT}/readme_example" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "docs_readme_example: the README's example exits ${rc} (the box did not come to rest):\n${out}${err}")
endif()
message(STATUS "docs_readme_example: the README's example compiles and the box comes to rest")
