#!/usr/bin/env bash
# The ParaView GUI with the PPIRay plugin, captured from a private Xvfb:
#   Documentation/paraview/make_screenshot.sh   ->  Documentation/paraview/paraview-gui.png
# Needs a built tree (Module/run build) and Pillow for /usr/bin/python3.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
display=":${PPIRAY_SCREENSHOT_DISPLAY:-93}"
Xvfb "$display" -screen 0 1600x1000x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $paraview $xvfb 2>/dev/null || true; rm -rf "$home"' EXIT
sleep 2
# A private home: no welcome dialog, no output window popping up for the
# mapper's warnings.
home="$(mktemp -d)"
mkdir -p "$home/.config/ParaView"
cat > "$home/.config/ParaView/ParaView5.11.0.ini" <<'INI'
[General]
GeneralSettings.ShowWelcomeDialog=false
OutputMessages.AlwaysOpenForNewMessages=false

[pqClientMainWindow]
Position=@Point(0 0)
Size=@Size(1600 1000)
INI
HOME="$home" DISPLAY="$display" PPIRAY_ROOT="$root" \
  PV_PLUGIN_PATH="$root/build/lib/paraview-5.11/plugins/PPIRay" \
  paraview --script="$here/gui_scene.py" -geometry 1600x1000+0+0 >/dev/null 2>&1 &
paraview=$!
sleep "${PPIRAY_SCREENSHOT_WAIT:-25}"
/usr/bin/python3 - "$display" "$here/paraview-gui.png" <<'PY'
import sys
from PIL import ImageGrab
ImageGrab.grab(xdisplay=sys.argv[1]).save(sys.argv[2])
PY
echo "wrote $here/paraview-gui.png"
