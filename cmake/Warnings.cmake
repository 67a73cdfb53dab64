# hylios_warnings: an interface target carrying the project's warning flags.
add_library(hylios_warnings INTERFACE)
target_compile_options(hylios_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
  -Wno-sign-conversion)
