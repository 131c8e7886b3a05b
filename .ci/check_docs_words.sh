#!/usr/bin/env bash
# Fails when a tracked file (git ls-files) narrates how sepax was made
# instead of what it is: numbered work periods, rounds of work, branch
# names, commit hashes, who did what.  The history of the project is in
# CHANGELOG.md (by version) and in git log.
#
# Looked for, case-insensitive (the patterns below, assembled from pieces so
# that this file does not match them itself; nothing is excluded):
#   - the words for a numbered work period or its plural, a "speed" or
#     numbered "round" of work;
#   - branch talk: the current branch, a branch named with hyphens;
#   - who did what: people and their roles;
#   - commit hashes: "commit(s) HASH", and in Markdown files any bare
#     7-12 digit hex word with letters and digits.
#
# Usage: bash .ci/check_docs_words.sh   (exit 0 clean, 1 hits, 77 no git checkout)
set -euo pipefail
cd "$(dirname "$0")/.."
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "check_docs_words: not a git checkout, nothing to check" >&2
  exit 77
fi

period='ses''sions?'
rnd='rou''nds?'
words="\\b(${period}|speed ${rnd}|${rnd} [0-9]+|this bra""nch|bra""nch [a-z0-9]+-[a-z0-9-]+|the lea""d's|other engin""eers|comm""its? \`?[0-9a-f]{7,40})\\b"
hash='(?<![0-9A-Za-z_.#-])(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,12}(?![0-9A-Za-z_])'

status=0
if git grep -n -I -i -P "$words"; then status=1; fi
if git grep -n -I -P "$hash" -- '*.md'; then status=1; fi
if [ "$status" != 0 ]; then
  echo "check_docs_words: the lines above describe how the project was made (work periods," \
       "rounds, branches, commits, people); say what the code is, and put history in CHANGELOG.md" >&2
else
  echo "check_docs_words: no tracked file narrates its own making"
fi
exit "$status"
