"""The paper sizes a scene (``drawing.paper``) and ``drafting render --paper`` accept: a module of its own so that
the command line's parser reads them without loading the scene reader (units, the engine)."""

PAPERS = ("A4", "A3")
