// A module instance's C API (web/api/f2_web.cpp) as JavaScript calls: the
// page's workers and the node tests use this one wrapper.
'use strict';

function wrapF2Module(m) {
  return {
    buildName: () => m.UTF8ToString(m._f2_build_name()),
    /// The scene text (empty: the default scene) → {ok, lastFrame, diagnostics}.
    setScene(text) {
      const size = m.lengthBytesUTF8(text) + 1;
      const pointer = m._malloc(size);
      m.stringToUTF8(text, pointer, size);
      const json = m.UTF8ToString(m._f2_set_scene(pointer));
      m._free(pointer);
      return JSON.parse(json);
    },
    /// Rows [y0, y1) of the frame as RGBA bytes (a copy), or null without a scene.
    render(frame, width, height, y0, y1) {
      const pointer = m._f2_render(frame, width, height, y0, y1);
      if (!pointer) return null;
      return new Uint8ClampedArray(m.HEAPU8.subarray(pointer, pointer + (y1 - y0) * width * 4));
    },
  };
}

if (typeof module !== 'undefined') module.exports = {wrapF2Module};
