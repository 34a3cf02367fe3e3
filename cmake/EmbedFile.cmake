# cmake -DINPUT=file -DOUTPUT=file.cpp -DSYMBOL=name -DHEADER=path.h -P EmbedFile.cmake
# Writes `std::span<const unsigned char> SYMBOL()` returning the file's bytes
# (a binary file: a font), declared in HEADER.
file(READ "${INPUT}" F2_HEX HEX)
string(LENGTH "${F2_HEX}" F2_HEX_LENGTH)
math(EXPR F2_SIZE "${F2_HEX_LENGTH} / 2")
# 0xab,0xcd,... on one line: compilers read it as fast as any layout.
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," F2_BYTES "${F2_HEX}")
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${INPUT}; do not edit.\n#include \"${HEADER}\"\n\nnamespace f2 {\nstd::span<const unsigned char> ${SYMBOL}() {\n    static constexpr unsigned char kBytes[${F2_SIZE}] = {\n${F2_BYTES}};\n    return kBytes;\n}\n}  // namespace f2\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
