"""The unit names read without pint (drafting.scene.unit_table) carry exactly pint's factor and root units,
so a scene reads the same whether a name is in the table or looked up in pint."""

import pytest

from drafting.scene import units
from drafting.scene.unit_table import KNOWN


def test_every_known_unit_is_pints_own():
    for name, (factor, root) in KNOWN.items():
        pint_factor, pint_root = units._pint_root(name)
        assert factor == pint_factor and dict(root) == dict(pint_root), name


def test_a_scene_in_common_units_is_read_without_pint():
    import subprocess
    import sys
    code = ("import sys\nfrom drafting.scene.reader import load_scene\nfrom drafting.study.worked import builtin_example\n"
            "load_scene(builtin_example())\nprint('pint' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


def test_a_name_outside_the_table_is_still_pints():
    assert "yard" not in KNOWN
    assert abs(units.to_si("1 yard", "length", "mm") - 0.9144) < 1e-12
    with pytest.raises(units.UnitError, match="is not a known unit name"):
        units.to_si("1 zorkmid", "length", "mm")
    assert units.to_si("2 mm", "length", "mm") == 0.002
