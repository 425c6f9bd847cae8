#!/usr/bin/env bash
# Gradescope's image set-up (book §B.8): the lab, uploaded as the autograder's source
# (/autograder/source), installs what it needs and builds the class's build once, so that each
# submission costs only its own files. AUTOGRADER_ROOT and RTLAB_LAB move the layout (tests).
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
lab=${RTLAB_LAB:-$root/source}
cd "$lab"
./lab grade-class --prepare --chapters "${RTLAB_CHAPTERS:-$(cmake -DGET=RTLAB_RELEASED -P tools/settings.cmake)}"
