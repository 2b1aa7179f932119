#!/bin/bash
# scripts/check_doc_links.py on a tree of known breaches: exactly the three broken links are
# reported, at their lines, and the exit status is 1; the good links, the outside one and the
# same-page anchor pass.
here="$(cd "$(dirname "$0")" && pwd)"
out="$(/usr/bin/python3 "$here/../../../scripts/check_doc_links.py" "$here")"
status=$?
expected="README.md:5: ](docs/missing.md): no such file
docs/a.md:5: ](sub/c.md#no-such-heading): no heading with anchor #no-such-heading
docs/sub/c.md:3: ](../../missing.png): no such file"
if [ "$status" -ne 1 ] || [ "$out" != "$expected" ]; then
  echo "exit $status, got:"; echo "$out"; echo "expected:"; echo "$expected"
  exit 1
fi
echo "the three breaches reported, exit 1"
