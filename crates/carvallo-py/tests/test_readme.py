"""The README's and the guide's Python examples run as written: the ```python block of the
README's `## Python` section and the notebook-style block of the guide's Python chapter
(`docs/guide/src/python.md`) are executed in a scratch directory holding
`data/benchmark-1pct.txt`; their printed lines equal the `# -> ` lines of the block, and the
guide's example writes the eigenvalue figure."""

import os
import pathlib
import re
import shutil
import subprocess
import sys


def python_blocks(text: str) -> list:
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def run_example(root, tmp_path, code: str) -> list:
    (tmp_path / "data").mkdir(exist_ok=True)
    shutil.copy(root / "data" / "benchmark-1pct.txt", tmp_path / "data")
    (tmp_path / "example.py").write_text(code)
    env = dict(os.environ, MPLBACKEND="Agg")
    out = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, env=env,
                         capture_output=True, text=True, check=True)
    expected = [line[len("# -> "):] for line in code.splitlines() if line.startswith("# -> ")]
    assert out.stdout.splitlines() == expected
    return expected


def test_the_readme_python_example_runs(root, tmp_path):
    readme = (root / "README.md").read_text()
    assert "pip install ./crates/carvallo-py" in readme
    section = readme.split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    blocks = python_blocks(section)
    assert len(blocks) == 1, "one ```python block in the README's Python section"
    assert len(run_example(root, tmp_path, blocks[0])) == 1


def test_the_guide_python_example_runs(root, tmp_path):
    blocks = python_blocks((root / "docs" / "guide" / "src" / "python.md").read_text())
    assert len(blocks) == 1, "one ```python block in the guide's Python chapter"
    assert len(run_example(root, tmp_path, blocks[0])) == 3
    png = (tmp_path / "eigenvalues.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000


def test_the_plant_chapter_python_examples_print_what_they_say(root, tmp_path):
    """Each `print(...)  # X` line of the ```python blocks of the plant chapter prints X."""
    blocks = python_blocks((root / "docs" / "guide" / "src" / "plant.md").read_text())
    assert len(blocks) == 5, "the state-space, frequency-response, time-response, closed-loop and driven-simulation examples"
    for code in blocks:
        expected = [line.split("  # ", 1)[1]
                    for line in code.splitlines() if line.startswith("print(") and "  # " in line]
        (tmp_path / "example.py").write_text(code)
        out = subprocess.run([sys.executable, "example.py"], cwd=tmp_path,
                             capture_output=True, text=True, check=True)
        assert out.stdout.splitlines() == expected
