#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fault injection through the CLI, as an unlucky user meets it: a full disk for every output
# format (a 1 MiB tmpfs, as root; skipped with the reason where mounting is not allowed), the
# input as its own output on that disk, device-node and symlink outputs, stdout on /dev/full,
# and SIGINT/SIGTERM at random points of `demo` (frames and video) and `apply`. Each checks the
# exit code, that nothing partial is left and that the input is intact.
#   tests/fault/fault-injection.sh FLAREKIT SAMPLES_DIR [gl|nogl]
# (nogl: a FLAREKIT_GL=OFF build; the demo cases, which need OpenGL, are skipped.)
set -uo pipefail
# shellcheck source=tests/support/undecodable-images.sh
source "$(dirname "$0")/../support/undecodable-images.sh"
cli="$1"
samples="$2"
gl="${3:-gl}"
work="$(mktemp -d /tmp/flarekit-fault.XXXXXX)"
mnt="$work/full"
failures=0
checks=0
pass() { checks=$((checks + 1)); }
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); checks=$((checks + 1)); }
cleanup() {
  mountpoint -q "$mnt" 2>/dev/null && umount "$mnt"
  rm -rf "$work"
}
trap cleanup EXIT

# No temporary or partial file anywhere under $1.
expect_no_leftovers() {
  local left
  left="$(find "$1" \( -name '.flarekit-tmp-*' -o -name '*.partial.mp4' \) 2>/dev/null)"
  if [ -n "$left" ]; then fail "$2: left behind: $left"; else pass; fi
}
# Every image under $1 decodes completely: one iinfo process computes every image's pixel statistics and
# reports a failed read in its output (an oiiotool per image cost half a second each, most of
# this script's time).
expect_complete_images() {
  local files
  mapfile -t files < <(find "$1" \( -name '*.png' -o -name '*.exr' \) 2>/dev/null)
  [ "${#files[@]}" -gt 0 ] || return 0
  local bad
  bad="$(undecodable_images "${files[@]}")"
  if [ -n "$bad" ]; then fail "$2: an image is not complete: $bad"; else pass; fi
}
expect_exit() {  # expected actual what
  if [ "$2" -eq "$1" ]; then pass; else fail "$3: exit $2, expected $1"; fi
}

cp "$samples/sunset.png" "$work/in.png"
in_sum="$(md5sum < "$work/in.png")"

# --- full disk ------------------------------------------------------------------------------
mkdir -p "$mnt"
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP full disk: not root (mounting a small tmpfs needs root)"
elif ! mount -t tmpfs -o size=1m tmpfs "$mnt" 2>/dev/null; then
  echo "SKIP full disk: mount -t tmpfs is not permitted here (a container without CAP_SYS_ADMIN)"
else
  cp "$work/in.png" "$mnt/in.png"
  dd if=/dev/zero of="$mnt/fill" bs=4k 2>/dev/null
  for ext in png jpg tif exr hdr bmp tga ppm webp; do
    "$cli" apply "$mnt/in.png" -o "$mnt/out.$ext" --light 400,200 2>"$work/err"
    rc=$?
    expect_exit 2 "$rc" "full disk, apply -o out.$ext"
    [ -e "$mnt/out.$ext" ] && fail "full disk: out.$ext exists" || pass
    grep -q "No space left on device" "$work/err" || fail "full disk .$ext: message: $(cat "$work/err")"
  done
  "$cli" postfx "$mnt/in.png" -o "$mnt/post.png" 2>/dev/null
  expect_exit 2 $? "full disk, postfx"
  "$cli" apply "$mnt/in.png" -o "$mnt/in.png" 2>/dev/null
  expect_exit 2 $? "full disk, apply IN -o IN"
  [ "$(md5sum < "$mnt/in.png")" = "$in_sum" ] && pass || fail "full disk: the input was changed"
  "$cli" visibility "$samples/scenes/sun-behind-trees.json" --json > "$mnt/v.json" 2>/dev/null
  rc=$?
  [ "$rc" -ne 0 ] && pass || fail "full disk: visibility --json > file exited 0"
  rm -f "$mnt/v.json" "$mnt/fill"
  # A disk that fills up during the demo: frames before are complete, nothing partial after.
  [ "$gl" = gl ] || echo "SKIP full disk during demo: built without OpenGL"
  [ "$gl" = gl ] && dd if=/dev/zero of="$mnt/fill" bs=4k count=160 2>/dev/null
  if [ "$gl" = gl ]; then
    "$cli" demo -o "$mnt/drive" --frames 40 --size 320x180 --no-video 2>/dev/null
    expect_exit 2 $? "full disk during demo"
  fi
  expect_complete_images "$mnt/drive" "full disk during demo"
  expect_no_leftovers "$mnt" "full disk"
  umount "$mnt"
fi

# --- devices, symlinks, stdout ----------------------------------------------------------------
"$cli" visibility "$samples/scenes/sun-behind-trees.json" --json > /dev/full 2>"$work/err"
rc=$?
[ "$rc" -ne 0 ] && grep -q "standard output" "$work/err" && pass || fail "stdout on /dev/full: exit $rc: $(cat "$work/err")"
mask="$work/mask.png"
oiiotool --pattern constant:color=0 480x272 1 -d uint8 -o "$mask"
# The device and the stdout link are this test's own (a full device made with mknod as root,
# a link to /proc/self/fd/1), so that a broken writer replaces them, not the system's.
full=/dev/full
if [ "$(id -u)" -eq 0 ] && mknod -m 666 "$work/full-device" c 1 7 2>/dev/null; then full="$work/full-device"; fi
stdout_link="$work/stdout-link"
ln -s /proc/self/fd/1 "$stdout_link"
"$cli" psp burnout --occluders "$mask" --sun 240,100 -o "$work/psp.png" --trace "$full" 2>/dev/null
expect_exit 2 $? "psp --trace $full"
[ -c "$full" ] && pass || fail "$full is no longer a character device"
lines="$("$cli" psp burnout --occluders "$mask" --sun 240,100 -o "$work/psp.png" --trace "$stdout_link" | wc -l)"
[ "$lines" -gt 10 ] && pass || fail "psp --trace (a link to stdout) wrote $lines lines to stdout"
[ -L "$stdout_link" ] && pass || fail "the link to stdout is no longer a link"
cp "$work/in.png" "$work/real.png"
ln -s real.png "$work/link.png"
"$cli" apply "$work/in.png" -o "$work/link.png" --light 400,200
expect_exit 0 $? "apply -o SYMLINK"
[ -L "$work/link.png" ] && pass || fail "the output symlink was replaced by a file"
[ "$(md5sum < "$work/real.png")" != "$in_sum" ] && pass || fail "the symlink's target was not written"
# A link to the input is the input: refused before any work, the input untouched.
cp "$work/in.png" "$work/real.png"
"$cli" apply "$work/real.png" -o "$work/link.png" --light 400,200 2>/dev/null
expect_exit 2 $? "apply IN -o SYMLINK-TO-IN"
[ "$(md5sum < "$work/real.png")" = "$in_sum" ] && pass || fail "the input behind the link changed"
ln -s dangling-target.png "$work/dangling.png"
"$cli" apply "$work/in.png" -o "$work/dangling.png" --light 400,200
expect_exit 0 $? "apply -o DANGLING-SYMLINK"
[ -L "$work/dangling.png" ] && [ -f "$work/dangling-target.png" ] && pass || fail "dangling symlink output"
mkfifo "$work/fifo.png"
( cat "$work/fifo.png" > "$work/from-fifo.png" ) &
"$cli" apply "$work/in.png" -o "$work/fifo.png" --light 400,200
expect_exit 0 $? "apply -o FIFO"
wait
[ -p "$work/fifo.png" ] && pass || fail "the FIFO was replaced"
oiiotool "$work/from-fifo.png" -o "$work/decoded.exr" >/dev/null 2>&1 && pass || fail "the FIFO did not carry a complete PNG"
[ "$(md5sum < "$work/in.png")" = "$in_sum" ] && pass || fail "the input was changed"
expect_no_leftovers "$work" "devices and links"

# --- interrupts -------------------------------------------------------------------------------
# A signal at a random point: the exit code is 128 + signal (or 0 when the run had finished
# before the signal came), nothing partial is left, every image is complete, no ffmpeg remains.
interrupt_trial() {  # signal delay_ms kind
  local sig="$1" delay="$2" kind="$3"
  local dir="$work/int-$kind-$sig-$delay" pid rc
  mkdir -p "$dir"
  if [ "$kind" = demo ]; then
    "$cli" demo -o "$dir/drive" --frames 24 --size 320x180 >/dev/null 2>"$dir/err" &
  else
    "$cli" apply "$samples/sunset-hdr.exr" -o "$dir/out.exr" --preset sun-wide \
      --layers "$dir/layers" 2>"$dir/err" &
  fi
  pid=$!
  sleep "$(awk "BEGIN {print $delay / 1000}")"
  local sent=1
  kill -s "$sig" "$pid" 2>/dev/null || sent=0
  wait "$pid"
  rc=$?
  local want=$((128 + $(kill -l "$sig")))
  if [ "$sent" -eq 1 ] && [ "$rc" -ne "$want" ] && [ "$rc" -ne 0 ]; then
    fail "$kind SIG$sig after ${delay} ms: exit $rc, expected $want: $(head -c 300 "$dir/err")"
  elif [ "$sent" -eq 1 ] && [ "$rc" -eq "$want" ] && [ -s "$dir/err" ] &&
      [ "$(grep -c '^flarekit: ' "$dir/err")" -ne 1 ]; then
    # (An empty stderr: the signal came while the dynamic loader was still starting the
    # process, before flarekit's handlers existed; nothing had been written.)
    fail "$kind SIG$sig after ${delay} ms: expected one flarekit line on stderr: $(cat "$dir/err")"
  else
    pass
  fi
  sleep 0.1
  if pgrep -f "ffmpeg.*$dir" >/dev/null; then fail "$kind SIG$sig: ffmpeg still running"; pkill -f "ffmpeg.*$dir"; else pass; fi
  expect_no_leftovers "$dir" "$kind SIG$sig after ${delay} ms"
  expect_complete_images "$dir" "$kind SIG$sig after ${delay} ms"
  # apply's layers: complete files, or no folder at all (never an empty one).
  if [ -d "$dir/layers" ] && [ -z "$(ls -A "$dir/layers")" ]; then
    fail "$kind SIG$sig after ${delay} ms: an empty layers folder was left"
  else
    pass
  fi
}
# Each signal lands at a random point of the job's own run: its length is measured first (the
# demo takes about a second on 2 cores, apply a fifth of one; fixed delays of up to 4 s mostly
# signalled a process that had already finished).
run_ms() {  # kind -> how long one uninterrupted run takes, in ms
  local dir="$work/timing-$1" start
  mkdir -p "$dir"
  start=$(date +%s%N)
  if [ "$1" = demo ]; then
    "$cli" demo -o "$dir/drive" --frames 24 --size 320x180 >/dev/null 2>&1
  else
    "$cli" apply "$samples/sunset-hdr.exr" -o "$dir/out.exr" --preset sun-wide \
      --layers "$dir/layers" 2>/dev/null
  fi
  echo $(( ($(date +%s%N) - start) / 1000000 + 1 ))
}
apply_ms=$(run_ms apply)
demo_ms=1
[ "$gl" = gl ] && demo_ms=$(run_ms demo)
RANDOM=${FLAREKIT_FAULT_SEED:-$$}
echo "interrupt trials with seed $RANDOM (a run: apply ${apply_ms} ms, demo ${demo_ms} ms)"
for sig in INT TERM; do
  for trial in 1 2 3; do
    [ "$gl" = gl ] && interrupt_trial "$sig" $((RANDOM % demo_ms)) demo
    interrupt_trial "$sig" $((RANDOM % apply_ms)) apply
  done
done

# SIGTERM to the job PID (a child of this shell) and its exit: sets rc and stop_ms.
terminate_timed() {
  local start
  start=$(date +%s%N)
  kill -s TERM "$1"
  wait "$1"
  rc=$?
  stop_ms=$(( ($(date +%s%N) - start) / 1000000 ))
}

# lens render with many sources: a line per source on stderr (not a terminal here), and SIGTERM
# stops it within 2 s wherever it is (Slurm waits 30 s before SIGKILL), with the interrupted line
# last and nothing written. 8 wavelengths: the lens's ghosts are traced once for all sources
# before the first is drawn (8 s on a 2-core VM; 24 wavelengths took 41 s, and over 30 s under
# the sanitizers), then each source takes milliseconds.
lens_dir="$work/lens-term"
mkdir -p "$lens_dir"
"$cli" lens render angenieux-double-gauss "$samples/sunset-hdr.exr" -o "$lens_dir/out.exr" \
  --light all --max-sources 256 --threshold 0.05 --spectral 8 --grid 96 2>"$lens_dir/err" &
pid=$!
for _ in $(seq 1 600); do grep -q "source 1 of" "$lens_dir/err" && break; sleep 0.05; done
grep -q "source 1 of [0-9]* drawn" "$lens_dir/err" && pass || fail "lens render: no per-source progress: $(head -c 300 "$lens_dir/err")"
sleep 0.3
terminate_timed "$pid"
echo "lens render stopped ${stop_ms} ms after SIGTERM (exit $rc)"
[ "$rc" -eq 143 ] && pass || fail "lens render SIGTERM: exit $rc, expected 143"
[ "$stop_ms" -lt 2000 ] && pass || fail "lens render took ${stop_ms} ms to stop after SIGTERM"
tail -n 1 "$lens_dir/err" | grep -q "^flarekit: .*interrupted by SIGTERM" && pass ||
  fail "lens render SIGTERM: the last line is not the interrupted line: $(tail -n 2 "$lens_dir/err")"
[ ! -e "$lens_dir/out.exr" ] && pass || fail "lens render SIGTERM: an output was written"
expect_no_leftovers "$lens_dir" "lens render SIGTERM"

# The same on the GL backend with one light and a spectral render: the GPU runs behind the draw
# loop (llvmpipe drew such a render for half a minute after a SIGTERM before), so the loop keeps
# it at most two small batches behind (40 s on llvmpipe, 36 of them drawing). SIGTERM 6 s in.
if [ "$gl" = gl ]; then
  "$cli" lens render angenieux-double-gauss "$samples/sunset-hdr.exr" -o "$lens_dir/gl.exr" \
    --backend gl --spectral 16 --grid 64 2>"$lens_dir/gl-err" &
  pid=$!
  sleep 6
  terminate_timed "$pid"
  echo "lens render --backend gl stopped ${stop_ms} ms after SIGTERM (exit $rc)"
  [ "$rc" -eq 143 ] && pass || fail "lens render --backend gl SIGTERM: exit $rc, expected 143: $(head -c 300 "$lens_dir/gl-err")"
  [ "$stop_ms" -lt 2000 ] && pass || fail "lens render --backend gl took ${stop_ms} ms to stop after SIGTERM"
  [ ! -e "$lens_dir/gl.exr" ] && pass || fail "lens render --backend gl SIGTERM: an output was written"
fi

echo "fault injection: $checks checks, $failures failed"
[ "$failures" -eq 0 ]
