#!/usr/bin/env bash
# The systemd units as shipped: every unit of deploy/systemd started as systemd would start it
# (systemd_exec.py: its EnvironmentFile= files from deploy/systemd/env, its ExecStart=, its
# StateDirectory=), all at once on the test's domain, each must stay up for 30 s (a unit that exits
# is restarted into failed by systemd) and be seen on plumb/status. Only the domain is the test's,
# and a port that another program of this machine holds is moved (said below).
# usage: units_as_shipped.sh SOURCE_DIR BIN_DIR DOMAIN
set -uo pipefail
src=$1 bin=$2
export PLUMB_DOMAIN_ID=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
start_work_with_programs
root=$work/root
mkdir -p "$root/opt/plumb" "$root/etc/plumb"
ln -s "$bin" "$root/opt/plumb/bin"
cp "$src"/deploy/systemd/env/*.env "$root/etc/plumb/"
sed -i "s/^PLUMB_DOMAIN_ID=.*/PLUMB_DOMAIN_ID=$PLUMB_DOMAIN_ID/" "$root/etc/plumb/plumb.env"
port_taken() { python3 -c 'import socket, sys; s = socket.socket(); s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1); s.bind(("", int(sys.argv[1])))' "$1" 2> /dev/null && return 1 || return 0; }
for pair in "display.env --port" "display.env --foxglove-port" "wits.env --listen"; do
  set -- $pair
  port=$(sed -nE "s/.*$2 ([0-9]+).*/\1/p" "$root/etc/plumb/$1")
  if [ -n "$port" ] && port_taken "$port"; then
    new=$(free_port)
    sed -i "s/$2 $port/$2 $new/" "$root/etc/plumb/$1"
    echo "note: port $port is taken on this machine: $1 uses $new for this test"
  fi
done

declare -A unit_pid
for unit in "$src"/deploy/systemd/*.service; do
  name=$(basename "$unit")
  instance=""
  [[ $name == *@.service ]] && instance=board && name=${name/@/@board}
  env -i python3 "$here/systemd_exec.py" "$root" "$unit" $instance > "$work/$name.log" 2>&1 &
  unit_pid[$name]=$!
  pids+=($!)
done
# 30 s, looking every second: a unit that exits early is reported at once.
for ((i = 0; i < 30; ++i)); do
  for name in "${!unit_pid[@]}"; do kill -0 "${unit_pid[$name]}" 2> /dev/null || break 2; done
  sleep 1
done
"$bin/plumb" status --wait 5 > "$work/status.txt" 2>&1
for name in $(printf '%s\n' "${!unit_pid[@]}" | sort); do
  program=${name%%.service}; program=${program%%@*}
  if ! kill -0 "${unit_pid[$name]}" 2> /dev/null; then
    fail "$name exited within 30 s: $(tail -3 "$work/$name.log")"
  elif ! grep -qE "[[:space:]]$program(/|[[:space:]])" "$work/status.txt"; then
    fail "$name runs but is not on plumb/status: $(cat "$work/status.txt")"
  else
    pass "$name up for 30 s from its shipped environment, on plumb/status: $(sed -n 2p "$work/$name.log" | cut -c1-150)"
  fi
done
finish
