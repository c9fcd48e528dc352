#!/usr/bin/env bash
# Starts `mpiexec -np 2 pvserver` on a free port and runs the client test
# against it. Arguments: MPIEXEC PVSERVER PVPYTHON SCRIPT [script args...].
set -u
mpiexec=$1 pvserver=$2 pvpython=$3 script=$4
shift 4
port=$((20000 + RANDOM % 20000))
log=$(mktemp)
"$mpiexec" -np 2 "$pvserver" --server-port=$port > "$log" 2>&1 &
server=$!
for _ in $(seq 1 60); do
  grep -q "Accepting connection" "$log" && break
  sleep 0.5
done
cat "$log"
"$pvpython" "$script" --port "$port" "$@"
status=$?
kill $server 2> /dev/null
wait $server 2> /dev/null
if [ $status -ne 0 ]; then
  echo "--- pvserver output ---"
  cat "$log"
fi
rm -f "$log"
exit $status
