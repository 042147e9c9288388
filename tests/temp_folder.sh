#!/bin/sh
# temp_folder.sh new|left DIR: the suite's temporary folder (CTest gives every test TMPDIR=DIR).
#   new:  made empty before the first test (what a killed test left last time goes).
#   left: after the last test: fails naming every entry a test left behind, then removes them.
set -eu
mode=$1 dir=$2
case $mode in
  new) rm -rf -- "$dir" && mkdir -p -- "$dir" ;;
  left)
    [ -d "$dir" ] || exit 0
    left=$(ls -A -- "$dir")
    rm -rf -- "$dir"
    if [ -n "$left" ]; then
      echo "left behind in the suite's temporary folder:"
      echo "$left"
      exit 1
    fi
    echo "nothing left behind in $dir" ;;
  *) echo "usage: temp_folder.sh new|left DIR" >&2; exit 2 ;;
esac
