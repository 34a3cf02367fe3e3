#!/usr/bin/env bash
# output_safety_check.sh CASE F2 FAKEBIN DIR SCENE: one case of "no broken file
# under a real name" (docs/robustness.md, "Output you can trust"), run in DIR
# (emptied first). FAKEBIN holds the fake ffmpeg (fake_ffmpeg.cpp). Exit 77 =
# skipped, with the reason on stdout.
set -u
case=$1 f2=$2 fakebin=$3 dir=$4 scene=$5
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
. "$(dirname "$0")/../skip.sh"
# run EXPECTED_EXIT ARGS...: f2 ARGS..., output in ./out.txt; checks the exit code.
run() {
  local want=$1
  shift
  "$f2" "$@" >out.txt 2>&1
  local code=$?
  cat out.txt
  [ "$code" -eq "$want" ] || fail "exit $code, expected $want: f2 $*"
}
# no_temporaries [DIR]: no temporary file of ours is left.
no_temporaries() {
  local left
  left=$(ls -A "${1:-.}" | grep -e '\.tmp-')
  [ -z "$left" ] || fail "temporary files left: $left"
}
small=(render "$scene" --size 64x48)

case $case in
disk-full-fake)  # ffmpeg says "No space left on device" and exits 0
  F2_FAKE_FFMPEG=enospc PATH="$fakebin:$PATH" run 1 "${small[@]}" --frames 0-2 -o v.mp4
  grep -q "No space left on device" out.txt || fail "the message does not say why"
  [ ! -e v.mp4 ] || fail "v.mp4 was written"
  no_temporaries
  ;;
silent-junk)  # ffmpeg exits 0 silently with a file that is no video: the probe finds it
  command -v ffprobe >/dev/null || skip_missing "no ffprobe: only a probe can tell"
  F2_FAKE_FFMPEG=silent-junk PATH="$fakebin:$PATH" run 1 "${small[@]}" --frames 0-2 -o v.webm
  grep -q "ffprobe" out.txt || fail "the message does not say the probe failed"
  [ ! -e v.webm ] || fail "v.webm was written"
  no_temporaries
  ;;
disk-full-tmpfs)  # the real ffmpeg on a real full file system
  command -v ffmpeg >/dev/null || skip_missing "no ffmpeg"
  mkdir full
  mount -t tmpfs -o size=64k tmpfs full 2>/dev/null || skip_impossible "cannot mount a tmpfs (not root, or no CAP_SYS_ADMIN)"
  trap 'umount "$dir/full"' EXIT
  head -c 61440 /dev/zero >full/filler  # 4 KiB left: less than any of the videos
  for ext in gif webm mp4; do
    run 1 render "$scene" --size 320x240 --frames 0-23 -o full/v.$ext
    grep -q "No space left on device" out.txt || fail "$ext: the message does not say the disk is full"
    [ "$(ls -A full)" = filler ] || fail "left on the full disk: $(ls -A full)"
  done
  ;;
devices)  # -o a device: written directly, never replaced by a regular file
  mknod null c 1 3 2>/dev/null && mknod full c 1 7 2>/dev/null || skip_impossible "cannot create device nodes (mknod needs root)"
  run 0 "${small[@]}" -o null
  [ -c null ] || fail "the device 'null' was replaced"
  run 1 "${small[@]}" -o full
  grep -q "No space left on device" out.txt || fail "writing /dev/full did not fail with ENOSPC"
  [ -c full ] || fail "the device 'full' was replaced"
  "$f2" "${small[@]}" -o /dev/stdout 2>out.txt | cat >piped.png || { cat out.txt; fail "-o /dev/stdout into a pipe failed"; }
  [ "$(head -c 4 piped.png | od -An -c | tr -d ' ')" = "211PNG" ] || fail "-o /dev/stdout did not write the PNG into the pipe"
  ln -s null null.mp4
  run 1 "${small[@]}" --frames 0-1 -o null.mp4
  grep -q "character device" out.txt || fail "a video onto a device is not refused clearly"
  [ -c null ] && [ -L null.mp4 ] || fail "the device or its link changed"
  no_temporaries
  ;;
symlinks)  # a symbolic link is followed: the file it names is replaced, the link stays
  mkdir real
  echo old >real/f.png
  ln -s real/f.png link.png
  ln -s real/new.png dangling.png
  run 0 "${small[@]}" -o link.png
  [ -L link.png ] || fail "link.png is no longer a symbolic link"
  [ "$(head -c 4 real/f.png | od -An -c | tr -d ' ')" = "211PNG" ] || fail "real/f.png was not replaced by the PNG"
  run 0 "${small[@]}" -o dangling.png
  [ -L dangling.png ] && [ -s real/new.png ] || fail "a dangling link's file was not created through it"
  if command -v ffmpeg >/dev/null; then
    echo old >real/v.gif
    ln -s real/v.gif v.gif
    run 0 "${small[@]}" --frames 0-1 -o v.gif
    [ -L v.gif ] && [ "$(head -c 3 real/v.gif)" = "GIF" ] || fail "the video did not go through the link"
  fi
  no_temporaries
  no_temporaries real
  ;;
protocol-names)  # names ffmpeg would read as protocols are plain files
  command -v ffmpeg >/dev/null || skip_missing "no ffmpeg"
  run 0 "${small[@]}" --frames 0-1 -o file:y.gif
  [ "$(head -c 3 file:y.gif)" = "GIF" ] || fail "file:y.gif is not the GIF"
  [ ! -e y.gif ] || fail "y.gif was written"
  "$f2" "${small[@]}" --frames 0-1 -o pipe:x.gif >stdout.bin 2>out.txt || { cat out.txt; fail "pipe:x.gif failed"; }
  [ "$(head -c 3 pipe:x.gif)" = "GIF" ] || fail "pipe:x.gif is not the GIF"
  [ ! -s stdout.bin ] || fail "the video went to standard output"
  no_temporaries
  ;;
long-name)  # a legal 254-byte file name, as a PNG and as a video
  name=$(printf 'a%.0s' $(seq 250))
  run 0 "${small[@]}" -o "$name.png"
  [ -s "$name.png" ] || fail "the 254-byte PNG name was not written"
  if command -v ffmpeg >/dev/null; then
    run 0 "${small[@]}" --frames 0-1 -o "$name.gif"
    [ -s "$name.gif" ] || fail "the 254-byte GIF name was not written"
  fi
  no_temporaries
  ;;
stdout-full)  # standard output on a full disk: an error, never exit 0 without the output
  [ -c /dev/full ] || skip_impossible "no /dev/full"
  for command in "info $scene" "check $scene" "export $scene --pov" "render $scene --size 8x6 -o -" \
    "render $scene --size 8x6 --pixel 1,1" "bench $scene --size 8x6 --frames 3 --warmup 0 --json"; do
    # shellcheck disable=SC2086  # the words of $command are its arguments
    "$f2" $command >/dev/full 2>out.txt
    code=$?
    cat out.txt
    [ "$code" -eq 1 ] || fail "exit $code, expected 1: f2 $command >/dev/full"
    grep -q "No space left on device" out.txt || fail "f2 $command >/dev/full does not say why it failed"
  done
  ;;
pattern-dirs)  # the frame number in the directory part: each frame's directory is made
  run 0 "${small[@]}" --frames 0-3 -o out_%d/f.png
  for f in 0 1 2 3; do [ -s out_$f/f.png ] || fail "out_$f/f.png missing"; done
  ;;
same-pid)  # two workers with the same PID (separate PID namespaces) on one directory
  command -v unshare >/dev/null || skip_missing "no unshare"
  real=$(command -v ffmpeg) || skip_missing "no ffmpeg"
  unshare -pf true 2>/dev/null || skip_impossible "unshare -pf is not permitted here"
  export F2_FAKE_FFMPEG=rendezvous F2_FAKE_FFMPEG_LOG=$dir/log F2_FAKE_FFMPEG_PARTIES=2 F2_REAL_FFMPEG=$real
  PATH="$fakebin:$PATH" unshare -pf "$f2" "${small[@]}" --frames 0-2 -o v.gif >w1.txt 2>&1 &
  p1=$!
  PATH="$fakebin:$PATH" unshare -pf "$f2" "${small[@]}" --frames 0-2 -o v.gif >w2.txt 2>&1 &
  p2=$!
  wait $p1; c1=$?
  wait $p2; c2=$?
  cat w1.txt w2.txt log
  [ "$c1" -eq 0 ] && [ "$c2" -eq 0 ] || fail "exits $c1 and $c2"
  [ "$(cut -d' ' -f1 log | sort -u)" = "1" ] || skip_impossible "the workers did not both run as PID 1"
  [ "$(cut -d' ' -f2 log | sort -u | wc -l)" -eq 2 ] || fail "both workers wrote the same temporary file"
  [ "$(head -c 3 v.gif)" = "GIF" ] || fail "v.gif is not a GIF"
  no_temporaries
  ;;
*) fail "unknown case $case" ;;
esac
echo "ok: $case"
