# Flags for our own targets only: f2_warnings (strict warnings) into every
# target we build; f2_opt (speed, CPU flags) into the core and the targets that
# need its speed; f2_fp comes with the core to everything that uses it.
add_library(f2_warnings INTERFACE)
target_compile_options(f2_warnings INTERFACE -Wall -Wextra -Werror
  # GCC 12 at -O3 reports impossible memcpy overlaps inside std::string's own
  # operator+ (GCC bug 105329/105651); not a finding in our code.
  $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-restrict>)

# Floating-point semantics, for every target that compiles the core's inline
# code (f2_core passes it on): no -ffast-math and no FMA contraction, so the
# packet and single-ray paths do the same IEEE operations and images do not
# depend on the ISA or on which copy of an inline function the linker keeps;
# only errno is dropped. No CPU flag here.
add_library(f2_fp INTERFACE)
target_compile_options(f2_fp INTERFACE -fno-math-errno -ffp-contract=off)

# Speed, for the core (PRIVATE) and the targets that drive its packet code.
add_library(f2_opt INTERFACE)
target_compile_options(f2_opt INTERFACE $<$<CONFIG:Release,RelWithDebInfo>:-O3>)
target_link_libraries(f2_opt INTERFACE f2_fp)
# Only these targets get CPU flags, so the rest compiles alike in every
# preset (the avx2 preset sets F2_CPU_FLAGS, not CMAKE_CXX_FLAGS).
set(F2_CPU_FLAGS "" CACHE STRING "CPU flags of the core and its packet tests when F2_NATIVE is OFF (e.g. -mavx2;-mfma)")
if(F2_NATIVE)
  target_compile_options(f2_opt INTERFACE -march=native)
elseif(F2_CPU_FLAGS)
  target_compile_options(f2_opt INTERFACE ${F2_CPU_FLAGS})
endif()

if(F2_SANITIZE)
  add_compile_options(-fsanitize=${F2_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${F2_SANITIZE})
endif()
