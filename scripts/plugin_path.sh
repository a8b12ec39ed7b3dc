# shellcheck shell=bash
# Sourced by scripts/meshlab_prefix.sh and meshlab_scripts/cross_parameterize.sh: which built
# plugin to use when none is named.
#
#   cbd_built_plugin ROOT
#
# Prints the newer of ROOT/build/plugin/libfilter_cbd.so (scripts/build.sh build) and
# ROOT/build-plugin/plugin/libfilter_cbd.so (the tests' plugin build); prints nothing and
# returns 1 when neither exists.
cbd_built_plugin() {
  local cand found=""
  for cand in "$1/build/plugin/libfilter_cbd.so" "$1/build-plugin/plugin/libfilter_cbd.so"; do
    if [ -f "$cand" ] && { [ -z "$found" ] || [ "$cand" -nt "$found" ]; }; then found="$cand"; fi
  done
  [ -n "$found" ] || return 1
  printf '%s\n' "$found"
}
