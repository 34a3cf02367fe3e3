# Sourced, not run: start_static_server DIR LOG serves DIR on a free local
# port with python3 -m http.server (which exits at once when its port is
# taken, so a few random ports are tried) and sets `server` (its pid) and
# `port`; both empty when none started.
start_static_server() {
  local dir=$1 log=$2 attempt
  server= port=
  for attempt in 1 2 3 4 5; do
    port=$(( 20000 + RANDOM % 20000 ))
    python3 -m http.server "$port" --bind 127.0.0.1 --directory "$dir" > "$log" 2>&1 &
    server=$!
    sleep 1
    kill -0 "$server" 2> /dev/null && return 0
    server= port=
  done
  return 1
}
