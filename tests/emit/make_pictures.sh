#!/usr/bin/env bash
# Write the pictures README.md and docs/pictures.md show (docs/pictures/*.png), each made by
# kinergy itself: a scene at its states (draw --state all), an impulse-momentum diagram of a worked
# solution (draw --figure), a frame of an animation (simulate --animate FILE.html, opened at
# #frame=K in headless Chromium), a page of derive --html, and a scene written with a wrong point
# beside the right one. Run it after a change to the drawings, look at the PNGs, and commit them:
#   bash tests/emit/make_pictures.sh [BUILD_DIR]      (BUILD_DIR defaults to build; needs chromium)
set -euo pipefail
cd "$(dirname "$0")/../.."
kinergy="${1:-build}/kinergy"
[ -x "$kinergy" ] || { echo "make_pictures: no $kinergy (build first, or pass the build directory)" >&2; exit 1; }
command -v chromium >/dev/null || { echo "make_pictures: chromium is not installed (bash .ci/setup --deps)" >&2; exit 1; }
out=docs/pictures
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
shot() {  # shot URL FILE WIDTH HEIGHT: a headless Chromium screenshot
  chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size="$3,$4" --virtual-time-budget=3000 \
    --screenshot="$2" "$1" >/dev/null 2>&1
}
"$kinergy" draw derivations/energy/bar_spring.yaml --state all -o "$out/scene_states.png"
"$kinergy" draw derivations/impact/sphere_hits_pivoted_bar.yaml --figure 2 -o "$out/impulse_momentum.png"
"$kinergy" draw derivations/momentum/disk_rolls_incline_time.yaml --figure 2 -o "$out/implied_support.png"
"$kinergy" draw derivations/energy/atwood_pulley.yaml --state all -o "$out/cords.png"
"$kinergy" draw derivations/energy/meshed_gears.yaml --state 1 -o "$out/gears_in_mesh.png"
"$kinergy" draw derivations/impact/pendulum_strikes_block.yaml --state 1 -o "$out/bob_and_floor.png"
"$kinergy" draw derivations/impact/bouncing_ball.yaml --state all -o "$out/ball_as_circle.png"
"$kinergy" draw derivations/energy/torsion_spring_bar.yaml --state 1 -o "$out/torsion_spring_at_pin.png"
"$kinergy" draw derivations/momentum/collar_rod_pin_reaction.yaml --figure 3 -o "$out/coupled_support.png"
"$kinergy" draw derivations/momentum/disk_axle_reaction.yaml --figure 2 -o "$out/reaction_labels.png"
"$kinergy" draw derivations/momentum/block_slides_on_cart.yaml --figure 3 -o "$out/arrow_on_its_body.png"
"$kinergy" draw derivations/momentum/gears_time_tooth_force.yaml --figure 2 -o "$out/tooth_impulse_on_rim.png"
# a page of the PDF with a figure, at the size it prints (its labels at 8 pt)
"$kinergy" derive derivations/energy/atwood_pulley.yaml --pdf "$tmp/atwood.pdf"
pdftoppm -f 2 -l 2 -r 90 -png "$tmp/atwood.pdf" "$tmp/page"
mv "$tmp"/page*.png "$out/pdf_page.png"
"$kinergy" simulate derivations/impact/bouncing_ball.yaml --until 1.5 --samples 300 --animate "$tmp/ball.html" >/dev/null
shot "file://$tmp/ball.html#frame=106" "$out/animation_frame.png" 760 760
"$kinergy" derive derivations/momentum/disk_axle_reaction.yaml --html "$tmp/page.html"
shot "file://$tmp/page.html" "$out/derive_html.png" 1000 1300
"$kinergy" draw derivations/energy/bar_spring.yaml --state 1 -o "$out/bar_spring_right.png"
"$kinergy" draw docs/examples/bar_spring_wrong_point.yaml --state 1 -o "$out/bar_spring_wrong.png"
echo "make_pictures: wrote $(ls "$out" | wc -l) pictures in $out"
