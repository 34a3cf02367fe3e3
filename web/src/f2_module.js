// A module instance's C API (web/api/f2_web.cpp) as JavaScript calls: the
// page's workers and the node tests use this one wrapper.
'use strict';

function wrapF2Module(m) {
  /// A C copy of a JavaScript string (the caller frees it).
  function allocate(text) {
    const size = m.lengthBytesUTF8(text) + 1;
    const pointer = m._malloc(size);
    m.stringToUTF8(text, pointer, size);
    return pointer;
  }
  return {
    buildName: () => m.UTF8ToString(m._f2_build_name()),
    /// The scene text (empty: the default scene) → {ok, lastFrame, diagnostics}.
    setScene(text) {
      const pointer = allocate(text);
      const json = m.UTF8ToString(m._f2_set_scene(pointer));
      m._free(pointer);
      return JSON.parse(json);
    },
    /// Rows [y0, y1) of the frame as RGBA bytes (a copy), or null without a
    /// scene. view: {antialias (N: N x N samples), yaw, pitch (degrees), zoom}
    /// turns the camera about the scene (all 0 and zoom 1: the scene's camera).
    render(frame, width, height, y0, y1, view = {}) {
      const {antialias = 1, yaw = 0, pitch = 0, zoom = 1} = view;
      const pointer = m._f2_render(frame, width, height, y0, y1, antialias, yaw, pitch, zoom);
      if (!pointer) return null;
      return new Uint8ClampedArray(m.HEAPU8.subarray(pointer, pointer + (y1 - y0) * width * 4));
    },
    /// A language server request (web/api/f2_lsp_web.cpp): "open" {text},
    /// "textDocument/completion" and "textDocument/hover" {position},
    /// "f2/languageLists" → its JSON result.
    lsp(method, params) {
      const methodPointer = allocate(method), paramsPointer = allocate(JSON.stringify(params));
      const json = m.UTF8ToString(m._f2_lsp(methodPointer, paramsPointer));
      m._free(methodPointer);
      m._free(paramsPointer);
      return JSON.parse(json);
    },
  };
}

if (typeof module !== 'undefined') module.exports = {wrapF2Module};
