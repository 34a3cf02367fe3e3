# Flags for our own targets only: link f2_warnings (strict warnings) and
# f2_opt (speed) into every target we build.
add_library(f2_warnings INTERFACE)
target_compile_options(f2_warnings INTERFACE -Wall -Wextra -Werror
  # GCC 12 at -O3 reports impossible memcpy overlaps inside std::string's own
  # operator+ (GCC bug 105329/105651); not a finding in our code.
  $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-restrict>)

add_library(f2_opt INTERFACE)
# No -ffast-math and no FMA contraction: the packet and single-ray paths do the
# same IEEE operations, so images do not depend on the ISA; only errno is dropped.
target_compile_options(f2_opt INTERFACE $<$<CONFIG:Release,RelWithDebInfo>:-O3> -fno-math-errno -ffp-contract=off)
if(F2_NATIVE)
  target_compile_options(f2_opt INTERFACE -march=native)
endif()

if(F2_SANITIZE)
  add_compile_options(-fsanitize=${F2_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${F2_SANITIZE})
endif()
