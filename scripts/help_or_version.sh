# Sourced first by every script in scripts/, with the script's own "$@" and its usage line in
# $usage: --help (or -h) prints that line and the script's header comment, --version the
# project version, and the script stops there, before it installs, builds or runs anything.
case "${1:-}" in
  -h | --help)
    echo "usage: $usage"
    echo
    sed -n '2,/^[^#]/ { /^#/ s/^# \{0,1\}//p }' "$0"
    exit 0
    ;;
  --version)
    echo "$(basename "$0") $(sed -n 's/^project(weft VERSION \([0-9.]*\).*/\1/p' \
      "$(dirname "$0")/../CMakeLists.txt")"
    exit 0
    ;;
esac
