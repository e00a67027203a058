"""Every whole scene in the documents passes `cosim check` without a warning: each ```yaml
block that starts with `time:` in README.md, docs/ and the folders' READMEs, checked as
a scene in configs/ would be (its relative paths, e.g. meshes/, resolve as there).
Blocks that show part of a scene (a section, a key) are not scenes and are left out.

    test_docs_scenes.py COSIM WORK

COSIM is the cosim program, WORK a folder for the scenes.
"""

import re
import shutil
import subprocess
import sys
import unittest
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
COSIM, WORK = sys.argv[1], Path(sys.argv[2])


def documents():
    yield REPO / "README.md"
    yield from sorted((REPO / "docs").rglob("*.md"))
    for readme in sorted(REPO.rglob("README.md")):
        if not readme.relative_to(REPO).parts[0].startswith(("build", ".", "docs")) and readme.parent != REPO:
            yield readme


def scenes():
    for document in documents():
        for block in re.findall(r"```ya?ml\n(.*?)```", document.read_text(), re.S):
            if block.startswith("time:"):
                yield document.relative_to(REPO), block


class DocumentedScenes(unittest.TestCase):
    def test_every_whole_scene_is_valid(self):
        shutil.rmtree(WORK, ignore_errors=True)
        WORK.mkdir(parents=True)
        (WORK / "meshes").symlink_to(REPO / "configs" / "meshes")
        checked = 0
        for document, block in scenes():
            with self.subTest(document=str(document), scene=checked):
                scene = WORK / f"scene{checked}.yaml"
                scene.write_text(block)
                r = subprocess.run([COSIM, "check", scene], cwd=WORK, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, text=True, timeout=60)
                self.assertEqual(r.returncode, 0, f"{document}:\n{r.stdout}")
                self.assertNotIn("warning", r.stdout, f"{document}:\n{r.stdout}")
            checked += 1
        # README.md's, docs/scenes.md's and the tracker's at least: the search found them.
        self.assertGreaterEqual(checked, 3)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], *sys.argv[3:]])
