#!/usr/bin/env bash
# A throw-away PostgreSQL 15 server for the test suite, from Debian's
# postgresql-15 package, touching nothing else on the machine:
#   eval "$(scripts/postgresql-test-server.sh start DIR)"   # sets HYDROCOEF_TEST_POSTGRESQL
#   scripts/postgresql-test-server.sh stop DIR
# `start` makes a new cluster in DIR (initdb, trust authentication, no TCP:
# it listens on a Unix socket in DIR only), starts it, creates database
# hydrocoef_test and prints the export line of its URL. PostgreSQL refuses to
# run as root, so as root the server runs as user nobody. `stop` stops it
# (immediately) and removes DIR; it is safe to call when nothing runs.
# The server skips fsync (a test server's data need not survive a power
# cut) unless HYDROCOEF_PG_FSYNC=on (benchmarks: bench/import_throughput_backends.sh).
set -euo pipefail
action=${1:?usage: postgresql-test-server.sh start|stop DIR}
dir=${2:?usage: postgresql-test-server.sh start|stop DIR}
bin=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n 1)
[[ -x "$bin/initdb" ]] || { echo "postgresql-test-server: no PostgreSQL server binaries (apt-get install postgresql-15)" >&2; exit 1; }
port=54329
as_owner() {
  if [[ $(id -u) -eq 0 ]]; then runuser -u nobody -- "$@"; else "$@"; fi
}

case "$action" in
  start)
    mkdir -p "$dir"
    [[ $(id -u) -eq 0 ]] && chown nobody:nogroup "$dir"
    chmod 700 "$dir"
    as_owner "$bin/initdb" -D "$dir/data" -U hydrocoef --auth=trust --encoding=UTF8 --locale=C.UTF-8 >"$dir/initdb.log" 2>&1 ||
      { cat "$dir/initdb.log" >&2; exit 1; }
    as_owner "$bin/pg_ctl" -D "$dir/data" -l "$dir/server.log" -w -t 60 \
      -o "-c listen_addresses='' -c unix_socket_directories='$dir' -p $port -c fsync=${HYDROCOEF_PG_FSYNC:-off} -c max_connections=60" \
      start >/dev/null || { cat "$dir/server.log" >&2; exit 1; }
    "$bin/createdb" -h "$dir" -p "$port" -U hydrocoef hydrocoef_test
    echo "export HYDROCOEF_TEST_POSTGRESQL='postgresql:///hydrocoef_test?host=$dir&port=$port&user=hydrocoef'"
    ;;
  stop)
    if [[ -f "$dir/data/postmaster.pid" ]]; then
      as_owner "$bin/pg_ctl" -D "$dir/data" -m immediate -w stop >/dev/null 2>&1 || true
    fi
    rm -rf "$dir"
    ;;
  *) echo "usage: postgresql-test-server.sh start|stop DIR" >&2; exit 2 ;;
esac
