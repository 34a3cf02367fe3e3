#!/usr/bin/env bash
# install_deps_check.sh SOURCE_DIR CMAKE WORK_DIR
# scripts/run.sh installs only what building and running f2 and the viewer
# needs; scripts/test.sh installs the rest (issue 12). Checked without
# installing anything: apt-get, dpkg-query and sudo are stand-ins that record
# what would be installed on a machine that has nothing. Then the build that
# run.sh configures is configured with the test and benchmark libraries
# hidden, so it cannot need them.
set -euo pipefail
src=$1 cmake=$2 work=$3
rm -rf "$work"
mkdir -p "$work/bin"
fail() { echo "FAIL: $*"; exit 1; }

cat > "$work/bin/dpkg-query" <<'EOF'
#!/bin/sh
exit 1
EOF
cat > "$work/bin/apt-get" <<EOF
#!/bin/sh
echo "\$@" >> "$work/apt-get.log"
EOF
cat > "$work/bin/sudo" <<'EOF'
#!/bin/sh
exec "$@"
EOF
for tool in localedef locale; do printf '#!/bin/sh\nexit 0\n' > "$work/bin/$tool"; done
chmod +x "$work"/bin/*

# The packages install-deps.sh MODE would install on an empty machine.
installs() {
  rm -f "$work/apt-get.log"
  PATH="$work/bin:$PATH" "$src/scripts/install-deps.sh" "$@" > /dev/null
  grep '^install ' "$work/apt-get.log" | tr ' ' '\n' | grep -v '^-' | grep -v '^install$' | sort
}
run_list=$(installs --run)
all_list=$(installs)
echo "run.sh installs: $(echo $run_list)"

for p in g++ cmake ninja-build libpng-dev libcli11-dev qt6-base-dev nlohmann-json3-dev; do
  grep -qx -- "$p" <<<"$run_list" || fail "install-deps.sh --run does not install $p, which the build needs"
done
# What only tests, benchmarks, videos, POV-Ray, plots, fuzzing and editors need.
for p in clang povray gnuplot-nox ffmpeg libgtest-dev libbenchmark-dev libembree-dev neovim imagemagick \
         parallel clang-format xvfb nodejs npm; do
  ! grep -qx -- "$p" <<<"$run_list" || fail "install-deps.sh --run installs $p, which only the tests need"
  # Node.js comes with the full list only where npm is missing (a Node.js of its own is kept).
  case $p in nodejs | npm) command -v npm > /dev/null && continue ;; esac
  grep -qx -- "$p" <<<"$all_list" || fail "install-deps.sh (for test.sh) does not install $p"
done

# scripts/web.sh --install: the browser page on a machine that has nothing.
web_list=$(installs --web)
for p in cmake ninja-build emscripten nlohmann-json3-dev libstb-dev python3; do
  grep -qx -- "$p" <<<"$web_list" || fail "install-deps.sh --web does not install $p, which web.sh needs"
done
! grep -qx -- qt6-base-dev <<<"$web_list" || fail "install-deps.sh --web installs Qt, which the page does not need"
grep -q 'scripts/install-deps.sh" --web$' "$src/scripts/web.sh" || fail "web.sh --install does not use install-deps.sh --web"

grep -q '^scripts/install-deps.sh --run$' "$src/scripts/run.sh" || fail "run.sh does not use install-deps.sh --run"
grep -q '^scripts/install-deps.sh$' "$src/scripts/test.sh" || fail "test.sh does not install everything"

# run.sh's configuration on a machine without the test libraries: GoogleTest
# and Google Benchmark hidden from find_package, configuring must still work.
"$cmake" -S "$src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DF2_BUILD_TESTS=OFF \
  -DF2_BUILD_BENCH=OFF -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "run.sh's configuration needs more than it installs"; }
echo "ok"
