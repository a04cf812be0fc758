#!/usr/bin/env bash
# tests/cli/faults.sh BINARY — the `shitsukan` tool when writing fails (make test-cli): disk
# full (`ulimit -f`, /dev/full), a missing, read-only or read-only-mounted directory, a
# read-only file, a directory in the way, a later file of a multi-file command failing, and
# SIGINT / SIGTERM while files are being written. Each run must exit non-zero with ONE
# message naming the path and the reason, leave no file under the requested names and no
# temporary, and keep the old files intact. A case this machine cannot produce is skipped
# with a printed reason. Last line: "cli fault tests: N passed, 0 failed, K skipped".
set -u
BIN="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
WORK="$(mktemp -d /tmp/shitsukan_faults.XXXXXX)"
chmod 755 "$WORK"  # the read-only cases run as another user, who must reach it
trap 'chmod -R u+w "$WORK" 2>/dev/null; rm -rf "$WORK"' EXIT
cd "$WORK"
pass=0
fail=0
skip=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
skipped() { skip=$((skip + 1)); echo "SKIP: $*"; }
OLD="the old file"

# failed RC DIR WANT... : the last run (rc RC, stderr in err.txt) failed as it must: rc not 0
# (and not 2, a flag error), every WANT text in stderr, no "wrote", no temporary in DIR
failed() {
    local rc="$1" dir="$2"; shift 2
    if [ "$rc" = 0 ] || [ "$rc" = 2 ]; then bad "exit status $rc ($(head -c 300 err.txt))"; return 1; fi
    for want in "$@"; do
        if ! grep -qF -- "$want" err.txt; then bad "message lacks '$want': $(head -c 300 err.txt)"; return 1; fi
    done
    if grep -q "wrote" err.txt; then bad "claims to have written: $(cat err.txt)"; return 1; fi
    local left; left="$(ls -A "$dir" | grep '^\.' || true)"
    if [ -n "$left" ]; then bad "temporaries left in $dir: $left"; return 1; fi
    return 0
}
absent() {  # absent FILE...: none of them exists
    for f in "$@"; do if [ -e "$f" ]; then bad "$f exists after a failed run"; return 1; fi; done
    return 0
}
intact() {  # intact FILE...: each still holds $OLD
    for f in "$@"; do
        if [ "$(cat "$f" 2>/dev/null)" != "$OLD" ]; then bad "$f was not kept ($(head -c 40 "$f" | od -c | head -1))"; return 1; fi
    done
    return 0
}

# --- disk full ---
"$BIN" marble --size 16 -o hm --quiet 2> /dev/null
"$BIN" normals hm_height16.png -o /dev/full --quiet 2> err.txt
failed $? . "/dev/full" "No space left on device" && ok
"$BIN" ist --N 3 --K 4 > /dev/full 2> err.txt
failed $? . "standard output" "No space left on device" && ok
mkdir quota && echo "$OLD" > quota/m_albedo.png
( ulimit -f 16; exec "$BIN" marble --size 256 -o quota/m --quiet ) 2> err.txt
failed $? quota "quota/m_albedo.png" "File too large" && intact quota/m_albedo.png && ok
# a multi-file command: the first file is past the limit; the second file's old copy stays
echo "$OLD" > quota/l_normal.png
( ulimit -f 64; exec "$BIN" leather --size 512 -o quota/l --quiet ) 2> err.txt
failed $? quota "File too large" && absent quota/l_height16.png quota/l_pattern.svg && \
    intact quota/l_normal.png && ok

# --- directories ---
"$BIN" marble --size 64 -o nodir/m --quiet 2> err.txt
failed $? . "nodir/m_albedo.png" "No such file or directory" && absent nodir && ok
mkdir way_albedo.png
"$BIN" marble --size 64 -o way --quiet 2> err.txt
failed $? . "way_albedo.png" "Is a directory" && [ -d way_albedo.png ] && ok

# --- read-only directory and file: as root permission bits do not hold, so run as nobody ---
as_other=()
if [ "$(id -u)" != 0 ]; then
    as_other=(env)
elif command -v setpriv > /dev/null && \
     setpriv --reuid=65534 --regid=65534 --clear-groups "$BIN" version > /dev/null 2>&1; then
    as_other=(setpriv --reuid=65534 --regid=65534 --clear-groups)
fi
if [ ${#as_other[@]} = 0 ]; then
    skipped "read-only directory: running as root and cannot run the tool as nobody (setpriv)"
    skipped "read-only file: running as root and cannot run the tool as nobody (setpriv)"
else
    mkdir ro && chmod 555 ro
    "${as_other[@]}" "$BIN" marble --size 64 -o ro/m --quiet 2> err.txt
    failed $? ro "ro/m_albedo.png" "directory ro: Permission denied" && absent ro/m_albedo.png && ok
    mkdir open && chmod 777 open && echo "$OLD" > open/m_albedo.png && chmod 444 open/m_albedo.png
    "${as_other[@]}" "$BIN" marble --size 64 -o open/m --quiet 2> err.txt
    failed $? open "open/m_albedo.png" "Permission denied (the file is read-only)" && intact open/m_albedo.png && ok
fi
# --- a read-only file system: a read-only tmpfs in a private mount namespace ---
if [ "$(id -u)" = 0 ] && command -v unshare > /dev/null && mkdir rofs && \
   unshare -m sh -c "mount -t tmpfs -o ro none '$WORK/rofs'" 2> /dev/null; then
    unshare -m sh -c "mount -t tmpfs -o ro none '$WORK/rofs' && exec '$BIN' marble --size 64 \
        -o '$WORK/rofs/m' --quiet" 2> err.txt
    failed $? . "rofs/m_albedo.png" "Read-only file system" && ok
else
    skipped "read-only file system: needs root and a private mount namespace (unshare -m)"
fi

# --- a later file of a multi-file command fails: none of them appears, old ones are kept ---
mkdir set && mkdir set/s_pattern.svg && echo "$OLD" > set/s_normal.png
"$BIN" leather --size 64 -o set/s --float both --quiet 2> err.txt
failed $? set "set/s_pattern.svg" "Is a directory" && absent set/s_height16.png set/s_height.pfm && \
    intact set/s_normal.png && ok
mkdir bark && mkdir bark/b_trunk.obj && echo "$OLD" > bark/b.svg
"$BIN" bark --N_R 8 --N_H 6 -o bark/b --quiet 2> err.txt
failed $? bark "bark/b_trunk.obj" "Is a directory" && absent bark/b_cracks.png bark/b_nodes.csv \
    bark/b_springs.csv bark/b_triangles.csv && intact bark/b.svg && ok
mkdir wr && mkdir wr/w.png
"$BIN" wrinkly --mesh "$ROOT/examples/data/ridge.mesh" --grid-level 1 --size 16 \
    -o wr/w --quiet 2> err.txt
failed $? wr "wr/w.png" "Is a directory" && absent wr/w.obj && ok
mkdir mp && mkdir mp/m_ao.png
"$BIN" marble --size 64 -o mp/m --quiet 2> err.txt
failed $? mp "mp/m_ao.png" "Is a directory" && absent mp/m_albedo.png mp/m_height.exr && ok

# --- a signal while the files are written: leather holds its height map (written) while it
# encodes the normal map; marble's PNG is open while it is encoded ---
# interrupted SIGNAL STATUS DIR PATTERN RUN-ARGS...: starts the run, waits until a file whose
# name starts with PATTERN (the final name, or its temporary ".PATTERN") appears in DIR, sends
# SIGNAL; the run must die of it (STATUS = 128 + signal number) leaving nothing
interrupted() {
    local sig="$1" status="$2" dir="$3" pattern="$4"; shift 4
    set -m  # a job of its own: a non-interactive shell starts background jobs ignoring SIGINT
    # the signals at their default even if this shell was started ignoring them (a background
    # job of a non-interactive shell ignores SIGINT, and set -m cannot undo that)
    env --default-signal=INT,TERM "$BIN" "$@" --quiet 2> err.txt &
    local pid=$! seen=0
    set +m
    for _ in $(seq 1 3000); do
        if compgen -G "$dir/$pattern*" > /dev/null || compgen -G "$dir/.$pattern*" > /dev/null; then
            seen=1; break; fi
        kill -0 $pid 2> /dev/null || break
        sleep 0.01
    done
    kill -s "$sig" $pid 2> /dev/null
    wait $pid
    local rc=$?
    if [ $seen = 0 ]; then bad "$sig: no file of $pattern appeared before the run ended (rc $rc)"; return 1; fi
    if [ $rc != "$status" ]; then bad "$sig during $*: exit status $rc, not $status"; return 1; fi
    local left; left="$(ls -A "$dir" | grep '^\.' || true)"
    if [ -n "$left" ]; then bad "$sig: temporaries left in $dir: $left"; return 1; fi
    return 0
}
mkdir sig && echo "$OLD" > sig/l_normal.png
interrupted INT 130 sig l_height16.png leather --size 2048 -o sig/l && \
    absent sig/l_height16.png sig/l_pattern.svg && intact sig/l_normal.png && ok
mkdir term && echo "$OLD" > term/m_ao.png
interrupted TERM 143 term m_albedo.png. marble --size 2048 -o term/m && intact term/m_ao.png && \
    absent term/m_albedo.png && ok

echo "cli fault tests: $pass passed, $fail failed, $skip skipped"
[ $fail = 0 ]
