"""Run a notebook of this gallery without Jupyter and store its outputs: each code cell is executed in one
namespace, in the notebook's folder, and the value of its last expression is kept as Jupyter would show
it (``_repr_html_``, ``_repr_svg_`` or ``repr``).  The test suite runs ``api-example.ipynb`` this way.

Usage: ``python gallery/run_notebook.py gallery/api-example.ipynb`` (rewrites the file with its outputs).
"""

from __future__ import annotations

import ast
import contextlib
import io
import json
import os
import sys
from pathlib import Path


def _display(value) -> dict:
    data = {"text/plain": [repr(value)]}
    for method, mime in (("_repr_html_", "text/html"), ("_repr_svg_", "image/svg+xml")):
        if hasattr(value, method):
            data[mime] = [getattr(value, method)()]
    return data


def run(path: Path) -> dict:
    """The notebook at ``path`` with every code cell executed and its outputs filled in."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    ns: dict = {"__name__": "__main__"}
    here = Path.cwd()
    os.chdir(path.parent)
    try:
        count = 0
        for cell in nb["cells"]:
            if cell["cell_type"] != "code":
                continue
            count += 1
            tree = ast.parse("".join(cell["source"]))
            last = tree.body.pop() if tree.body and isinstance(tree.body[-1], ast.Expr) else None
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                exec(compile(tree, f"<cell {count}>", "exec"), ns)
                value = eval(compile(ast.Expression(last.value), f"<cell {count}>", "eval"), ns) if last else None
            outputs = []
            if out.getvalue():
                outputs.append({"output_type": "stream", "name": "stdout", "text": [out.getvalue()]})
            if value is not None:
                outputs.append({"output_type": "execute_result", "execution_count": count, "metadata": {},
                                "data": _display(value)})
            cell["outputs"], cell["execution_count"] = outputs, count
    finally:
        os.chdir(here)
    return nb


if __name__ == "__main__":
    target = Path(sys.argv[1])
    target.write_text(json.dumps(run(target), indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
