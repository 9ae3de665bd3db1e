"""The README's "Use from Python" snippet runs as written (in a scratch
folder holding the two shared maps it names), its `remesh` lines on the
quads it wrote, read back as a plain surface."""

import re

from conftest import REPO


def test_readme_snippet_runs(shared, tmp_path, monkeypatch):
    readme = (REPO / "README.md").read_text()
    section = readme.split("## Use from Python", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    assert len(blocks) == 1, "one python block in README's Use from Python"
    for rel in ("qex/fandisk_param.obj", "hexex/hand_q.hexex"):
        src = shared(rel)
        (tmp_path / src.name).symlink_to(src)
    monkeypatch.chdir(tmp_path)
    scope = {}
    exec(compile(blocks[0], "README.md", "exec"), scope)
    assert len(scope["quads"]) == 897 and len(scope["hexes"]) == 956
    assert scope["report"]["simplices"] == 11472
    assert (tmp_path / "quads.obj").is_file()
    # the written quads read back as a plain surface and remeshed
    assert scope["none"] is None and scope["SF"].shape == (2 * 897, 3)
    assert scope["rstats"]["topology"]["matches"] and len(scope["rquads"]) == scope["rstats"]["quads"] > 0
