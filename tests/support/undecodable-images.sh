# SPDX-License-Identifier: Apache-2.0
# Sourced by the shell tests (the docs' blocks, fault injection): whether every image given
# decodes completely. OpenImageIO's iinfo computes each one's pixel statistics, one process for
# them all, and reports a failed read in its output.
#   undecodable_images FILE...   prints up to 3 of iinfo's error lines; nothing when all decode
undecodable_images() {
  [ "$#" -gt 0 ] || return 0
  local stats
  stats="$(iinfo --stats "$@" 2>&1)"
  if grep -q -E "unable to compute|Error|error" <<<"$stats"; then
    grep -m 3 -E "unable to compute|Error|error" <<<"$stats" | tr '\n' ' '
  fi
}
