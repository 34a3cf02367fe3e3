#!/usr/bin/env bash
# video_check.sh FILE CODEC W H FRAMES FPS: ffprobe reads FILE back as one
# video stream with that codec, size, decoded frame count and frame rate, and
# no temporary file is left beside it.
set -eu
file=$1 codec=$2 w=$3 h=$4 frames=$5 fps=$6
[ -s "$file" ] || { echo "FAIL: $file missing"; exit 1; }
got=$(ffprobe -v error -select_streams v:0 -count_frames \
      -show_entries stream=codec_name,width,height,nb_read_frames,r_frame_rate -of default=nw=1 "$file")
echo "$got"
want="codec_name=$codec width=$w height=$h r_frame_rate=$fps/1 nb_read_frames=$frames"
for field in $want; do
  grep -qx "$field" <<<"$got" || { echo "FAIL: expected $field"; exit 1; }
done
ls -a "$(dirname "$file")" | grep -q "$(basename "$file")\.tmp-" && { echo "FAIL: temporary file left"; exit 1; }
echo "ok: $file"
