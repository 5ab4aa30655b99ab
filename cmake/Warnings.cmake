# Warnings for our own targets only: a non-exported interface target, so
# consumers of the installed package do not inherit our flags.
add_library(frictionref_warnings INTERFACE)
target_compile_options(frictionref_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual>)
