"""The README's Python example runs as written: its ```python block under `## Python` is
executed in a scratch directory holding `data/benchmark-1pct.txt`, its printed lines equal the
`# -> ` lines of the block, and it writes the eigenvalue figure."""

import os
import pathlib
import re
import shutil
import subprocess
import sys


def python_example(readme: str) -> str:
    section = readme.split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    assert len(blocks) == 1, "one ```python block in the README's Python section"
    return blocks[0]


def test_the_readme_python_example_runs(root, tmp_path):
    readme = (root / "README.md").read_text()
    assert "pip install ./crates/carvallo-py" in readme
    code = python_example(readme)
    (tmp_path / "data").mkdir()
    shutil.copy(root / "data" / "benchmark-1pct.txt", tmp_path / "data")
    (tmp_path / "example.py").write_text(code)
    env = dict(os.environ, MPLBACKEND="Agg")
    out = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, env=env,
                         capture_output=True, text=True, check=True)
    expected = [line[len("# -> "):] for line in code.splitlines() if line.startswith("# -> ")]
    assert len(expected) == 3
    assert out.stdout.splitlines() == expected
    png = (tmp_path / "eigenvalues.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000
