#!/usr/bin/env bash
# nvim_test.sh F2: Neovim's built-in LSP client opens data/broken.f2 through
# `F2 lsp` and checks where the diagnostics land, then renames a variable of
# data/included across its include (nvim_test.lua).
# Skipped (tests/skip.sh: skip_missing) when Neovim is not installed.
set -u
. "$(dirname "$0")/../skip.sh"
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v nvim >/dev/null 2>&1; then
  skip_missing "nvim is not installed (scripts/install-deps.sh installs Debian's neovim)"
fi
# A private home, so no user configuration or plugin takes part.
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
HOME=$home XDG_CONFIG_HOME=$home XDG_DATA_HOME=$home XDG_STATE_HOME=$home \
  F2=$1 SCENE=$here/data/broken.f2 INCLUDED=$here/data/included nvim --headless --clean -c "luafile $here/nvim_test.lua" 2>&1
