#!/usr/bin/env bash
# Drives the real vimg-editor under Xvfb with xdotool: vertex handles. Drags a polygon's vertex,
# double-clicks an edge to insert a vertex and drags it, chooses a vertex and deletes it, tries to
# delete below 3 vertices, drags a line's end; saves after each stage and checks the points;
# undoes the deletion. A resize by a handle with snap on lands on whole snap steps.
# usage: vertex_gui_test.sh PATH/TO/vimg-editor ARTIFACT_DIR   (screenshots and files stay there)
set -euo pipefail
editor=$(realpath "$1")
art=$2
here=$(cd "$(dirname "$0")" && pwd)
check() { python3 "$here/gui_check.py" "$@"; }
source "$here/gui_driver.sh"
gui_setup

cat >"$art/shapes.vimg" <<'VIMG'
<?xml version="1.0" encoding="UTF-8"?>
<vibroimage version="1.0" width="100" height="100">
  <surface id="poly" shape="polygon" points="20,20 60,20 60,60 20,60" period="2" relief="0.5" pattern="sine" gain="1"/>
  <line id="wire" x1="70" y1="80" x2="90" y2="80" width="1.5" frequency="175" damping="0.05" gain="1"/>
  <surface id="box" shape="rect" x="70.5" y="30" width="10" height="10" period="2" relief="0.5" pattern="sine" gain="1"/>
</vibroimage>
VIMG

current=vertices
start vertices "$art/shapes.vimg" --output none --recovery-dir "$art/recovery"
click_mm 40 40                      # select the polygon
drag_mm 60 20 70 10                 # drag a vertex
save_as "$art/moved.vimg"
check points "$art/moved.vimg" poly "20,20 70,10 60,60 20,60"

move_mm 40 60; sleep 0.2            # double-click the bottom edge: a vertex at (40, 60)
xdotool click --repeat 2 --delay 60 1; sleep 0.4
drag_mm 40 60 40 70                 # and drag it down
shot vertex-inserted
save_as "$art/inserted.vimg"
check points "$art/inserted.vimg" poly "20,20 70,10 60,60 40,70 20,60"

click_mm 20 20; key Delete          # choose a vertex and delete it
save_as "$art/deleted.vimg"
check points "$art/deleted.vimg" poly "70,10 60,60 40,70 20,60"
click_mm 20 60; key Delete          # down to 3
click_mm 40 70; key Delete          # refused: a polygon keeps 3 vertices
save_as "$art/three.vimg"
check points "$art/three.vimg" poly "70,10 60,60 40,70"
key ctrl+z                          # the last deletion undone
save_as "$art/undone.vimg"
check points "$art/undone.vimg" poly "70,10 60,60 40,70 20,60"

click_mm 80 80                      # the line: drag its right end
drag_mm 90 80 96 90
shot line-end-dragged
save_as "$art/line.vimg"
check points "$art/line.vimg" wire "70,80 96,90"

# Resize with snap on, as a move is snapped: the box (off the grid, right edge at 80.5 mm) by its
# right-middle handle, dragged 4.9 mm: the edge moves by whole snap steps (2 mm at zoom 2 on a
# 96 dpi screen), 4 mm, to 84.5 (snapping the mouse to the grid instead would give 86).
click_mm 75 35
drag_mm 80.5 35 85.4 35.2
save_as "$art/resized.vimg"
check box "$art/resized.vimg" box 70.5 30 14 10
quit_editor
echo "PASS: editor vertex GUI test (artifacts in $art)"
