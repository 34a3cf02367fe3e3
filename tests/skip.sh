# Sourced by the shell tests: the two ways a test may end without running.
#
# skip_missing REASON: a program or package the test needs is not installed.
#   Skipped (exit 77, CTest's SKIP_RETURN_CODE) with the reason; a failure
#   when F2_REQUIRE_ALL_TESTS=1, as .ci/run sets it: there every package can
#   be installed, so a missing one is a broken set-up, not a reason to skip.
# skip_impossible REASON: what the test needs cannot exist here whatever is
#   installed (permissions that root ignores, no right to mount): always a
#   skip. docs/robustness.md lists these.
skip_missing() {
  if [ "${F2_REQUIRE_ALL_TESTS:-}" = 1 ]; then
    echo "FAIL: $* (F2_REQUIRE_ALL_TESTS=1: nothing the tests need may be missing)"
    exit 1
  fi
  echo "SKIP: $*"
  exit 77
}
skip_impossible() {
  echo "SKIP: $*"
  exit 77
}
