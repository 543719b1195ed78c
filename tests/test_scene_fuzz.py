"""Whatever a user writes into a scene file, the answer is a scene or one SceneError sentence -- never a
traceback -- and a scene that reads either solves or raises a ConstructionError that says why."""

from __future__ import annotations

import copy
import math
import tomllib

from hypothesis import HealthCheck, given, settings, strategies as st

from constructions.errors import ConstructionError
from drafting.study.worked import builtin_example
from drafting.scene.reader import SceneError, scene_from_data
from drafting.study.study import Study
from drafting.scene.textsafe import printable

BASE = tomllib.loads(builtin_example().read_text())


def _paths(data, prefix=()):
    if isinstance(data, dict):
        for k, v in data.items():
            yield prefix + (k,)
            yield from _paths(v, prefix + (k,))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            yield prefix + (i,)
            yield from _paths(v, prefix + (i,))


PATHS = sorted(_paths(BASE), key=str)

scalars = st.one_of(
    st.integers(-10**6, 10**6), st.floats(allow_nan=True, allow_infinity=True), st.booleans(),
    st.text(max_size=12),
    st.sampled_from(["50 mm", "-3 in", "70 deg", "1e400 mm", "nan mm", "500 mm/s", "12 rpm", "0 rad/s",
                     "left of B->O1", "ahead of B", "behind C", "A3", "portrait", "kg", "mm", "", "O1", "C",
                     # hostile (issue 6): expressions, percentages, decimal commas, huge and tiny values
                     "9**9**9 mm", "2*3 mm", "50 percent", "500 percent", "0 dimensionless", "60,5 mm",
                     "1e30 mm", "1e-30 mm", "10 Hz", "\x00\x1b[2J", "\ufffe\uffff", "x" * 300]),
    st.sampled_from([10**400, -10**30, 2**1023 * 2, 1e300, 5e-324]))
values = st.recursive(scalars, lambda inner: st.one_of(st.lists(inner, max_size=3),
                                                       st.dictionaries(st.text(max_size=6), inner, max_size=3)),
                      max_leaves=6)


def _set(data, path, value):
    node = data
    for k in path[:-1]:
        node = node[k]
    if value is _DELETE:
        if isinstance(node, dict):
            del node[path[-1]]
        else:
            node.pop(path[-1])
    else:
        node[path[-1]] = value


_DELETE = object()


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(edits=st.lists(st.tuples(st.sampled_from(PATHS), st.one_of(values, st.just(_DELETE))),
                      min_size=1, max_size=3))
def test_any_edit_gives_a_scene_or_one_clear_sentence(edits):
    data = copy.deepcopy(BASE)
    for path, value in edits:
        try:
            _set(data, path, value)
        except (KeyError, IndexError, TypeError, AttributeError):
            continue                   # an earlier edit removed or replaced the parent
    try:
        scene = scene_from_data(data, "fuzz.toml")
        study = Study(scene).check()        # the family's checks: the assembly plan
    except SceneError as e:
        text = str(e)
        assert text.startswith("fuzz.toml: ") and "\n" not in text and "Traceback" not in text
        assert printable(text) == text and len(text) < 1500      # escaped, long values cut
        return
    assert math.isfinite(scene.angle) and math.isfinite(scene.omega) and scene.omega != 0
    try:
        study.comparisons
    except ConstructionError as e:
        assert "\n" not in str(e) and str(e)
