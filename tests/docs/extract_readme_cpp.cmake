# Writes the README's first ```cpp block to OUT (cmake -DREADME=... -DOUT=... -P this file), so
# that tests/CMakeLists.txt compiles and runs the example exactly as the README shows it.
file(READ ${README} text)
string(FIND "${text}" "```cpp\n" start)
if(start EQUAL -1)
  message(FATAL_ERROR "${README}: no ```cpp block")
endif()
math(EXPR start "${start} + 7")
string(SUBSTRING "${text}" ${start} -1 rest)
string(FIND "${rest}" "```" end)
string(SUBSTRING "${rest}" 0 ${end} code)
file(WRITE ${OUT}.new "// Generated from README.md (tests/docs/extract_readme_cpp.cmake).\n${code}")
file(COPY_FILE ${OUT}.new ${OUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUT}.new)
