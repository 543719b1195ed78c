"""The unit names the gallery and the defaults use, with pint's factor and root units for each (generated from
pint's registry; tests/test_units_table.py holds every row to pint): a scene written in these units is read
without loading pint (~0.1 s of a cold ``drafting render``).  Any other name is looked up in pint itself."""

KNOWN: dict[str, tuple[float, tuple[tuple[str, int | float], ...]]] = {
    'N': (1000.0, (('gram', 1), ('meter', 1), ('second', -2))),
    'W': (1000.0, (('gram', 1), ('meter', 2), ('second', -3))),
    'cm': (0.01, (('meter', 1),)),
    'deg': (0.017453292519943295, (('radian', 1),)),
    'degree': (0.017453292519943295, (('radian', 1),)),
    'degrees': (0.017453292519943295, (('radian', 1),)),
    'ft': (0.30479999999999996, (('meter', 1),)),
    'g': (1.0, (('gram', 1),)),
    'h': (3600.0, (('second', 1),)),
    'hour': (3600.0, (('second', 1),)),
    'in': (0.0254, (('meter', 1),)),
    'kN': (1000000.0, (('gram', 1), ('meter', 1), ('second', -2))),
    'kW': (1000000.0, (('gram', 1), ('meter', 2), ('second', -3))),
    'kg': (1000.0, (('gram', 1),)),
    'km': (1000.0, (('meter', 1),)),
    'lbf': (4448.221615260501, (('gram', 1), ('meter', 1), ('second', -2))),
    'm': (1.0, (('meter', 1),)),
    'min': (60.0, (('second', 1),)),
    'mm': (0.001, (('meter', 1),)),
    'ms': (0.001, (('second', 1),)),
    'rad': (1.0, (('radian', 1),)),
    'radian': (1.0, (('radian', 1),)),
    'revolution': (6.283185307179586, (('radian', 1),)),
    'rpm': (0.10471975511965977, (('radian', 1), ('second', -1))),
    's': (1.0, (('second', 1),)),
    'second': (1.0, (('second', 1),)),
    'um': (1e-06, (('meter', 1),)),
    'µm': (1e-06, (('meter', 1),)),
}
