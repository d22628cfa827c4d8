"""Every command's output for the samples, the built-in variants and scenes, pinned by its
digest (``tests/pinned.py``): a change of any of them is either a mistake or said in the
commit that makes it, with ``python tests/pinned.py --update``."""

import json

from pinned import MANIFEST, digests, outputs


def test_every_pinned_output_is_as_it_was():
    want = json.loads(MANIFEST.read_text(encoding="utf-8"))
    got = digests(outputs())
    assert sorted(got) == sorted(want), "the set of pinned outputs changed"
    changed = [name for name in want if got[name] != want[name]]
    assert not changed, (f"{len(changed)} pinned outputs changed: {', '.join(changed[:20])} "
                         "(python tests/pinned.py --write DIR shows them)")
