# Sourced by tests/cli/*.sh: expect_exit CODE MESSAGE ARGS... runs "$pathref" ARGS, requires exit
# CODE and, when MESSAGE is not empty, MESSAGE in its stdout or stderr (fixed string). stdout is
# left in $tmp/out, stderr in $tmp/err. Needs $pathref and $tmp.
expect_exit() {
  local want=$1 msg=$2; shift 2
  set +e; timeout 120 "$pathref" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?; set -e
  if [ "$got" != "$want" ]; then
    echo "FAIL: pathref $* exited $got, expected $want"; cat "$tmp/out" "$tmp/err"; exit 1
  fi
  [ -z "$msg" ] || grep -qF -- "$msg" "$tmp/out" "$tmp/err" ||
    { echo "FAIL: pathref $*: output lacks '$msg':"; cat "$tmp/out" "$tmp/err"; exit 1; }
}
