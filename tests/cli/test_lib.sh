# What the command-line test scripts share (sourced; `tmp` is the script's scratch folder).

fail() { echo "FAIL: $*"; exit 1; }

# expect_exit CODE MESSAGE COMMAND…: the command exits CODE with MESSAGE on the first line of stderr.
expect_exit() {
  expected_code=$1 expected=$2
  shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  code=$?
  [ "$code" -eq "$expected_code" ] || fail "'$*' exit $code (expected $expected_code); stderr: $(head -c 2000 "$tmp/err")"
  head -n 1 "$tmp/err" | grep -qF -- "$expected" || fail "'$*': expected '$expected', got: $(head -c 2000 "$tmp/err")"
}
