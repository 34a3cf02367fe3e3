# Sourced by the web tests after tests/skip.sh: `needs TOOL...` skips the
# test (skip_missing) unless each is there: emcc, node, chromium, or
# puppeteer (web/test's npm package), esbuild (web's, with CodeMirror). `root` is the repository.
needs() {
  for tool in "$@"; do
    case $tool in
      emcc) command -v emcc > /dev/null 2>&1 ||
        skip_missing "emcc is not installed (apt-get install emscripten; scripts/web.sh --install)" ;;
      node) command -v node > /dev/null 2>&1 ||
        skip_missing "node is not installed (scripts/install-deps.sh installs nodejs)" ;;
      chromium) command -v chromium > /dev/null 2>&1 ||
        skip_missing "chromium is not installed (apt-get install chromium)" ;;
      puppeteer) [ -d "$root/web/test/node_modules/puppeteer-core" ] ||
        skip_missing "npm package puppeteer-core is missing in web/test: run scripts/install-node-packages.sh" ;;
      esbuild) [ -x "$root/web/node_modules/.bin/esbuild" ] ||
        skip_missing "npm package esbuild (the page's editor bundle) is missing in web: run scripts/install-node-packages.sh" ;;
      *) echo "needs: unknown tool $tool"; exit 1 ;;
    esac
  done
}
