#!/bin/sh
# A help2man include file with each subcommand's --help (the subcommands read from `kinergy --help`):
#   sh cmake/man_subcommands.sh KINERGY OUT
set -e
kinergy=$1
out=$2
{
  echo "[SUBCOMMANDS]"
  for s in $("$kinergy" --help | awk '/^Subcommands:/ {f = 1; next} f && NF {print $1}'); do
    echo ".SS $s"
    echo ".nf"
    "$kinergy" "$s" --help | sed -e 's/\\/\\\\/g' -e 's/^\./\\\&./'
    echo ".fi"
  done
  echo "[SEE ALSO]"
  echo "The README and docs/ of the kinergy sources."
} > "$out"
