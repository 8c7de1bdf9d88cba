#!/usr/bin/env bash
# The local commands of the guides in docs/ run as written (issue 54 item 2): every indented
# `cyclopt-foot` line of docs/*.md (programs taken from the build, /tmp/ paths and output files moved
# into a temporary directory, trailing comments dropped) must exit 0. Commands that need a server
# are run by readme_quick_start and service_integration; job specs are checked by test_job_schema.
# usage: docs_commands.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
SOURCE=$1 BUILD=$2
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$SOURCE"
# /tmp/ is replaced before the build's path goes in: the build may itself live under /tmp.
grep -h -E '^    (build/client/)?cyclopt-foot ' docs/*.md | sed -E -e 's/^    //' -e 's/ +# .*$//' \
  -e "s#/tmp/#$WORK/#g" -e "s#--job-spec ([a-z_]+\.json)#--job-spec $WORK/\1#" \
  -e "s#^(build/client/)?cyclopt-foot#$BUILD/client/cyclopt-foot#" > "$WORK/commands"
N=$(wc -l < "$WORK/commands")
[ "$N" -ge 6 ] || { echo "FAIL: only $N cyclopt-foot commands in docs/"; exit 1; }
START=$(date +%s)
while IFS= read -r cmd; do
  echo "+ ${cmd//$WORK/TMP}"
  rc=0
  eval "$cmd" > "$WORK/out" 2>&1 || rc=$?
  [ "$rc" -eq 0 ] || { tail -5 "$WORK/out"; echo "FAIL: exit $rc of: $cmd"; exit 1; }
done < "$WORK/commands"
echo "docs/: $N cyclopt-foot commands ran in $(( $(date +%s) - START )) s"
