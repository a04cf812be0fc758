#!/usr/bin/env bash
# tests/cli/run.sh BINARY — the `shitsukan` tool's tests (make test-cli): each good run exits 0
# and makes its files (non-empty, the right kind); each bad flag or value exits 2 with ONE line
# on stderr naming the flag. Last line: "cli tests: N passed, 0 failed".
set -u
BIN="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
WORK="$(mktemp -d /tmp/shitsukan_cli.XXXXXX)"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# good RUN-ARGS... -- FILES...: exit 0 and every file exists, non-empty, PNGs with the signature
good() {
    local args=() files=() seen=0
    for a in "$@"; do
        if [ "$a" = "--" ]; then seen=1; continue; fi
        if [ $seen = 0 ]; then args+=("$a"); else files+=("$a"); fi
    done
    if ! "$BIN" "${args[@]}" --quiet > out.txt 2> err.txt; then
        bad "shitsukan ${args[*]} exited $? ($(head -c 300 err.txt))"; return
    fi
    for f in "${files[@]}"; do
        if [ ! -s "$f" ]; then bad "shitsukan ${args[*]}: $f missing or empty"; return; fi
        case "$f" in
        *.png) if [ "$(head -c 4 "$f" | od -An -c | tr -d ' ')" != "211PNG" ]; then
                   bad "$f is not a PNG"; return; fi ;;
        *.pfm) if ! head -c 2 "$f" | grep -q '^P[Ff]'; then bad "$f is not a PFM"; return; fi ;;
        *.obj) if ! grep -q '^f ' "$f"; then bad "$f has no faces"; return; fi ;;
        *.svg) if ! grep -q '<svg' "$f"; then bad "$f is not SVG"; return; fi ;;
        esac
    done
    ok
}

# refused WANT-IN-MESSAGE RUN-ARGS...: exit 2, exactly one stderr line containing the text
refused() {
    local want="$1"; shift
    "$BIN" "$@" > out.txt 2> err.txt
    local rc=$?
    if [ $rc != 2 ]; then bad "shitsukan $* exited $rc, not 2 ($(head -c 200 err.txt))"; return; fi
    if [ "$(wc -l < err.txt)" != 1 ]; then bad "shitsukan $*: stderr is not one line:"; cat err.txt; return; fi
    if ! grep -qF -- "$want" err.txt; then bad "shitsukan $*: message lacks '$want': $(cat err.txt)"; return; fi
    ok
}

# --- good runs ---
good marble --size 64 -o m -- m_albedo.png m_height16.png m_height.exr m_normal.png m_roughness.png m_ao.png
good marble --size 64 --tileable --float both -o mt -- mt_albedo.png mt_height.pfm mt_height.exr
cp mt_height.pfm m.pfm
good marble --size 64 --layer-period 8 --w 2 --alpha 0.7 --plane xy --at 10 -o ml -- ml_albedo.png
good wood --size 64 --k2 2 --x0 30 --y0 30 -o w -- w_albedo.png w_normal.png
good marble --size 64 --stripes "20,3,0.8;44,1.5,1.2" --i-min 10,20,30 --i-max 250,240,230 \
     -o ms -- ms_albedo.png
good leather --size 96 --section concave --float pfm --obj-step 8 -o croc -- croc_height16.png \
     croc_normal.png croc_pattern.svg croc_height.pfm croc_relief.obj croc_albedo.png croc_ao.png
good leather --size 64 --control "0,0.1,0.5,0.1,0.8,0.12,1,0" --D 0.2 --d 0.2 -o own -- \
     own_height16.png own_normal.png
good leather --size 64 --tileable -o tile -- tile_height16.png tile_normal.png
good leather --size 64 --tileable --layout triangular --D 0.25 -o tri -- tri_height16.png \
     tri_normal.png
good wrinkly --mesh "$ROOT/examples/data/ridge.mesh" --grid-level 2 --size 64 -o wr -- wr.obj wr.png
good wrinkly --mesh "$ROOT/examples/data/ridge.mesh" --form superposed --delta 0.6 --K 3 \
     --grid-level 2 --size 64 -o sp -- sp.obj sp.png
good bark --species pine --N_R 16 --N_H 12 -o pine -- pine_cracks.png pine.svg pine_nodes.csv \
     pine_springs.csv pine_triangles.csv pine_trunk.obj
good bark --species chinese_tallow --N_R 16 --N_H 12 --no-csv --kappa1 1.05 -o t -- t_cracks.png
good ist --N 3 --K 2 --
good version --
# marble baked onto an OBJ's uv map (the trunk the bark run wrote has uv), and a view
good marble --obj pine_trunk.obj --size 64 --view view.png -o baked -- baked_albedo.png view.png
# the tileable marble's PFM: 64 x 64 floats; ist prints N^K = 9 pairs after 2 comments
if [ "$(sed -n 2p mt_height.pfm)" = "64 64" ]; then ok; else bad "mt_height.pfm header $(sed -n 2p mt_height.pfm)"; fi
"$BIN" ist --N 3 --K 2 > ist.txt
if [ "$(grep -vc '^#' ist.txt)" = 9 ] && grep -q '^12 21$' ist.txt; then ok; else bad "ist table"; cat ist.txt; fi
# normals from any height map: the leather run's 16-bit PNG, the tileable marble's PFM
good normals own_height16.png -o own_n.png --strength 20 -- own_n.png
good normals --in m.pfm --wrap -o m_n.png -- m_n.png
"$BIN" normals /nonexistent.png -o x.png > out.txt 2> err.txt
rc=$?
if [ $rc = 1 ] && grep -q 'nonexistent.png' err.txt; then ok; else bad "normals of a missing file: rc $rc"; fi
# help cites the paper and exits 0
for c in marble wood leather wrinkly bark ist normals; do
    if "$BIN" $c --help > help.txt && grep -qE 'okada|tokai|fujimoto|hirota|§' help.txt; then ok
    else bad "$c --help"; fi
done

# --- refused: exit 2, one line naming the flag ---
refused "--k must be a number in [0, 1000]" marble --k abc
refused "--k must be a number in [0, 1000]" marble --k 1e9
refused "--R must be an integer in [1, 8]" marble --R 12
refused "--size must be an integer in [8, 16384]" marble --size 3
refused "--size must be an integer in [8, 8192]" leather --size 16384
refused "--size must be an integer" wood --size 1.5
refused "--seed must be an integer in [0, 4294967295]" marble --seed -4
refused "--beta must be a number" marble --beta nan
refused "--plane must be one of xz|xy|yz" marble --plane diagonal
refused "unknown flag --bogus" marble --bogus
refused "--tileable" wood --tileable
refused "--stripes must be c,w,alpha triples" marble --stripes "1,2"
refused "--stripes must be c,w,alpha triples" marble --stripes "1,0,1"
refused "--i-max must be r,g,b with each in [0, 255]" marble --i-max 1,2,300
refused "--i-min must be r,g,b" wood --i-min red
refused "--view needs --obj" marble --view x.png
refused "-o needs a value" marble -o
refused "--a must be a number in [0, 1]" leather --a 2
refused "--section must be one of convex|concave|two_segment" leather --section flat
refused "--layout" leather --layout hexagonal
refused "--control must be 8 numbers" leather --control "1,2,3"
refused "--control: " leather --control "0,0,1,1,0,0.5,0.1,0"
refused "--D must be a number" leather --D 0
refused "--mesh is required" wrinkly
refused "--N must be an integer in [2, 32]" wrinkly --N 1
refused "--delta must be" wrinkly --delta 1.5
refused "--species must be one of camphor|chinese_tallow|pine" bark --species oak
refused "--N_R must be an even integer" bark --N_R 17
refused "--kappa1 must be a number" bark --kappa1 0.9
refused "--K must be an integer in [0, 40]" ist --K 99
refused "--kind must be one of" ist --kind spiral
refused "--N, --K, --bases" ist --N 10 --K 7
refused "--strength must be a number in [0, 1e+06]" normals own_height16.png --strength -1
refused "a height map is required" normals
refused "-o must name a .png file" normals own_height16.png -o n.jpg
refused "unknown command" frobnicate
# an output name the command cannot write: refused before any work, nothing written
refused "-o is the prefix of the files written (<prefix>_...), not a .jpg file (got \"x.jpg\")" marble --size 8 -o x.jpg
refused "-o is the prefix of the files written" wood --size 8 -o x.tif
refused "--preview must name a .png file" marble --size 8 --preview d.jpg
refused "--view must name a .png file" marble --obj pine_trunk.obj --view v.jpg
refused "-o is the prefix of the files written" leather --size 8 -o croc.png
refused "-o is the prefix of the files written" bark -o pine.svg
refused "-o is the prefix of the files written" wrinkly --mesh broken.mesh -o wr.obj
for f in x.jpg x.jpg_albedo.png x.tif d.jpg v.jpg croc.png_height16.png pine.svg_cracks.png; do
    if [ -e "$f" ]; then bad "$f written by a refused run"; else ok; fi
done
refused "takes no value" marble --tileable=yes
refused "unexpected argument" marble stray
# a malformed control-mesh file: exit 1 with the line number
printf '2 2\n0 0 0 0\n1 0 0 x\n' > broken.mesh
"$BIN" wrinkly --mesh broken.mesh > out.txt 2> err.txt
rc=$?
if [ $rc = 1 ] && grep -q 'broken.mesh:3:' err.txt; then ok; else bad "broken.mesh: rc $rc $(cat err.txt)"; fi
printf 'v 0 0 0\nf 1 2 3\n' > broken.obj
"$BIN" marble --obj broken.obj > out.txt 2> err.txt
rc=$?
if [ $rc = 1 ] && grep -q 'broken.obj:2:' err.txt; then ok; else bad "broken.obj: rc $rc $(cat err.txt)"; fi

# a height map with a NaN, an infinity or slopes past a float's range: exit 1, the reason named
printf 'Pf\n3 1\n-1.0\n\0\0\0\0\0\0\300\177\0\0\0\0' > nan.pfm
printf 'Pf\n3 1\n-1.0\n\0\0\0\0\0\0\200\177\0\0\0\0' > inf.pfm
printf 'Pf\n3 1\n-1.0\n\346\261\141\177\0\0\0\0\346\261\141\377' > huge.pfm
for f in nan inf huge; do
    "$BIN" normals $f.pfm -o ${f}_n.png > out.txt 2> err.txt
    rc=$?
    if [ $rc = 1 ] && grep -q 'height_map_normals' err.txt && [ ! -e ${f}_n.png ]; then ok
    else bad "normals of $f.pfm: rc $rc $(cat err.txt)"; fi
done

# bark flags in range whose grown trunk makes a crack map past the memory budget: exit 1 with
# the budget's message, no crash, no map
for args in "--N_R 8 --N_H 4 --T 1000000" "--N_R 32 --N_H 16 --L0 100"; do
    "$BIN" bark $args -o big --quiet > out.txt 2> err.txt
    rc=$?
    if [ $rc = 1 ] && grep -q 'crack map of .* over the memory budget' err.txt && [ ! -e big_cracks.png ]; then ok
    else bad "bark $args: rc $rc $(cat err.txt)"; fi
done

# readers stop at once on an endless or binary input, and refuse out-of-range colours and
# over-long lines with the line number
timeout 20 "$BIN" marble --obj /dev/zero -o z > out.txt 2> err.txt
rc=$?
if [ $rc = 1 ] && grep -q '/dev/zero:1: NUL byte' err.txt; then ok; else bad "--obj /dev/zero: rc $rc $(cat err.txt)"; fi
printf '1 1\n0 0 0 0 1.5 0 0\n' > colour.mesh
"$BIN" wrinkly --mesh colour.mesh > out.txt 2> err.txt
rc=$?
if [ $rc = 1 ] && grep -q 'colour.mesh:2: the colour' err.txt; then ok; else bad "colour.mesh: rc $rc $(cat err.txt)"; fi
{ printf '2 1\n0 0 0 0'; head -c 1100 /dev/zero | tr '\0' ' '; printf '0 0 0 0\n'; } > long.mesh
"$BIN" wrinkly --mesh long.mesh > out.txt 2> err.txt
rc=$?
if [ $rc = 1 ] && grep -q 'long.mesh:2: line longer than 1024 bytes' err.txt; then ok; else bad "long.mesh: rc $rc $(cat err.txt)"; fi

# --- bark as a texture (--texture and its flags: a good run and a bad value each) ---
good bark --species pine --texture --N_R 16 --size 32 --float both -o bt -- bt_albedo.png \
     bt_height16.png bt_height.pfm bt_height.exr bt_normal.png bt_roughness.png bt_ao.png
good bark --species chinese_tallow --texture --N_R 16 --size 32 --normal directx --strength 3 \
     --ao-radius 4 --preview btp.png -o btd -- btd_normal.png btd_height.exr btp.png
good bark --species camphor --texture --N_R 16 --N_H 14 --size 16 --bevel 0.5 --relief 0.1 \
     --tone 0.3 -o bt2 -- bt2_albedo.png bt2_normal.png
if [ "$(sed -n 2p bt_height.pfm)" = "32 32" ]; then ok; else bad "bt_height.pfm header $(sed -n 2p bt_height.pfm)"; fi
refused "--size must be a power of two in [8, 8192] (got 48)" bark --texture --size 48
refused "--size must be an integer in [8, 8192]" bark --texture --size 4
refused "--bevel must be a number in [0.01, 4]" bark --texture --bevel 9
refused "--relief must be a number in [0, 1]" bark --texture --relief 2
refused "--tone must be a number in [0, 1]" bark --texture --tone -1
refused "add --texture" bark --size 64
refused "--normal shapes the --texture maps; add --texture" bark --normal directx
refused "--preview shapes the --texture maps; add --texture" bark --preview p.png
refused "--preview must name a .png file" bark --texture --preview p.jpg
refused "--normal must be one of opengl|directx" bark --texture --normal vulkan
refused "--float must be one of exr|pfm|both" bark --texture --float tiff
refused "--strength must be a number in [0, 10000]" bark --texture --strength -1
refused "--ao-radius must be a number in [1, 4096]" bark --texture --ao-radius 0
refused "--N_H must be >= 3 with --texture" bark --texture --N_H 2
refused "takes no value" bark --texture=yes

# --- wrinkly from the shell: a height map in, the map set out, camera/jitter/ramp flags ---
good wrinkly --height-map bt_height16.png --periodic --form superposed --K 2 --points 8 \
     --map-size 32 --size 64 --float both --preview hmp.png -o hm -- hm.obj hm.png \
     hm_height16.png hm_height.pfm hm_height.exr hm_albedo.png hm_normal.png hm_roughness.png \
     hm_ao.png hmp.png
good wrinkly --height-map bt_height.pfm --form superposed --K 2 --points 6 --extent 4 \
     --height-scale 0.5 --ramp sand --jitter-height 0.1 --jitter-color 0.02 --seed 3 \
     --azimuth 10 --elevation 45 --distance 3 --fov 30 --map-size 16 --size 48 -o hp -- \
     hp.png hp_height16.png
good wrinkly --height-map bt_height16.png --ramp "0:0,0,0;0.5:1,0,0;1:1,1,1" --points 5 \
     --map-size 16 --size 32 --grid-level 1 -o hr -- hr_albedo.png
good wrinkly --mesh "$ROOT/examples/data/ridge.mesh" --periodic --grid-level 2 --size 64 \
     --map-size 32 --normal directx -o rp -- rp.obj rp_height16.png rp_normal.png
good wrinkly --mesh "$ROOT/examples/data/fig21_terrain.mesh" --form superposed --K 2 \
     --grid-level 2 --jitter-height 0.12 --jitter-color 0.035 --size 64 --map-size 32 -o f21 -- \
     f21.png f21_albedo.png
if [ "$(sed -n 2p hm_height.pfm)" = "32 32" ]; then ok; else bad "hm_height.pfm header $(sed -n 2p hm_height.pfm)"; fi
refused "not both" wrinkly --mesh "$ROOT/examples/data/ridge.mesh" --height-map bt_height16.png
refused "--map-size must be a power of two in [8, 8192] (got 48)" wrinkly --height-map bt_height16.png --map-size 48
refused "--map-size must be an integer in [8, 8192]" wrinkly --height-map bt_height16.png --map-size 4
refused "--periodic needs --basis bspline" wrinkly --height-map bt_height16.png --periodic --basis bezier
refused "--points must be an integer in [4, 1024]" wrinkly --height-map bt_height16.png --points 2
refused "add --height-map" wrinkly --mesh "$ROOT/examples/data/ridge.mesh" --points 8
refused "--extent must be a number in [0.001, 10000]" wrinkly --height-map bt_height16.png --extent 0
refused "--height-scale must be a number in [0, 10000]" wrinkly --height-map bt_height16.png --height-scale -1
refused "--ramp: colour ramp \"heat\"" wrinkly --height-map bt_height16.png --ramp heat
refused "--jitter-height must be a number in [0, 100]" wrinkly --height-map bt_height16.png --jitter-height 200
refused "jitter the samples of --form superposed" wrinkly --height-map bt_height16.png --jitter-height 0.1
refused "--jitter-color must be a number in [0, 1]" wrinkly --height-map bt_height16.png --form superposed --jitter-color 2
refused "--azimuth must be a number in [-360, 360]" wrinkly --height-map bt_height16.png --azimuth 400
refused "--elevation must be a number in [1, 89]" wrinkly --height-map bt_height16.png --elevation 0
refused "--distance must be a number in [0.5, 50]" wrinkly --height-map bt_height16.png --distance 0.1
refused "--fov must be a number in [5, 120]" wrinkly --height-map bt_height16.png --fov 200
refused "takes no value" wrinkly --height-map bt_height16.png --periodic=1
refused "--preview must name a .png file" wrinkly --height-map bt_height16.png --preview p.exr
refused "-o is the prefix of the files written" wrinkly --height-map bt_height16.png -o t.exr
refused "--seed must be an integer in [0, 4294967295]" wrinkly --height-map bt_height16.png --seed -1
refused "--normal must be one of opengl|directx" wrinkly --height-map bt_height16.png --normal metal
refused "--float must be one of exr|pfm|both" wrinkly --height-map bt_height16.png --float hdr
refused "--strength must be a number in [0, 10000]" wrinkly --height-map bt_height16.png --strength -3
refused "--ao-radius must be a number in [1, 4096]" wrinkly --height-map bt_height16.png --ao-radius 9999
good wrinkly --height-map bt_height16.png --points 4 --map-size 16 --size 32 --grid-level 1 \
     --strength 2 --ao-radius 3 -o hs -- hs_ao.png hs_roughness.png
"$BIN" wrinkly --height-map /nonexistent.png > out.txt 2> err.txt
rc=$?
if [ $rc = 1 ] && grep -q 'nonexistent.png' err.txt; then ok; else bad "wrinkly --height-map of a missing file: rc $rc $(cat err.txt)"; fi
# --- map sets (docs/TOOL.md): every new flag runs, and refuses a bad value with one line ---
good marble --size 64 --tileable --look carrara --preview mp.png -o mc -- mc_albedo.png mp.png
good marble --size 64 --interpolation eq6 --normal directx -o me -- me_normal.png
good marble --size 64 --strength 6 --ao-radius 4 -o ma -- ma_ao.png ma_roughness.png
good wood --size 64 --look walnut -o ww -- ww_albedo.png
good leather --size 64 --look crocodile-back --tileable --preview lp.png -o lb -- lb_albedo.png \
     lp.png lb_height.exr
good marble --obj pine_trunk.obj --size 64 --gutter 2 -o bg -- bg_albedo.png bg_normal.png
refused "--look must be one of" marble --look oak
refused "--look must be one of" wood --look granite
refused "--look must be one of" leather --look lizard
refused "--interpolation must be one of smooth|eq6" marble --interpolation cubic
refused "--normal must be one of opengl|directx" marble --normal vulkan
refused "--float must be one of exr|pfm|both" leather --float tiff
refused "--strength must be a number in [0, 10000]" marble --strength -2
refused "--ao-radius must be a number in [1, 4096]" wood --ao-radius 0
refused "--gutter must be an integer in [0, 256]" marble --obj pine_trunk.obj --gutter 999
refused "--gutter needs --obj" marble --gutter 4
refused "--preview must name a .png file" leather --preview p.exr
# DirectX and OpenGL normal maps differ exactly in the green channel (g' = 255 - g)
"$BIN" marble --size 64 -o gl --quiet 2> /dev/null && "$BIN" marble --size 64 --normal directx -o dx --quiet 2> /dev/null
if /usr/bin/python3 -c "
import sys, numpy as np, OpenImageIO as oiio
a = oiio.ImageInput.open('gl_normal.png').read_image(oiio.UINT8).astype(int)
b = oiio.ImageInput.open('dx_normal.png').read_image(oiio.UINT8).astype(int)
sys.exit(0 if (a[:, :, 0] == b[:, :, 0]).all() and (a[:, :, 2] == b[:, :, 2]).all()
         and (a[:, :, 1] + b[:, :, 1] == 255).all() else 1)"; then ok; else bad "DirectX normal map: not OpenGL's with green flipped"; fi
# the same for `shitsukan normals --normal directx` from any height map
good normals own_height16.png --normal directx -o own_ndx.png --strength 20 -- own_ndx.png
refused "--normal must be one of opengl|directx" normals own_height16.png --normal vulkan
if /usr/bin/python3 -c "
import sys, numpy as np, OpenImageIO as oiio
a = oiio.ImageInput.open('own_n.png').read_image(oiio.UINT8).astype(int)
b = oiio.ImageInput.open('own_ndx.png').read_image(oiio.UINT8).astype(int)
sys.exit(0 if (a[:, :, 0] == b[:, :, 0]).all() and (a[:, :, 2] == b[:, :, 2]).all()
         and (a[:, :, 1] + b[:, :, 1] == 255).all() else 1)"; then ok; else bad "normals --normal directx: not OpenGL's with green flipped"; fi
# the EXR and PFM of one run hold the same floats: read back through OpenImageIO, bit for bit
for set in mt croc; do
    [ -e ${set}_height.exr ] || "$BIN" leather --size 96 --section concave --float both -o croc --quiet 2> /dev/null
    if /usr/bin/python3 "$ROOT/tests/cli/exr_readback.py" ${set}_height.exr ${set}_height.pfm > rb.txt 2>&1
    then ok; else bad "EXR read back: $(cat rb.txt)"; fi
done

echo "cli tests: $pass passed, $fail failed"
[ $fail = 0 ]
