"""A client that passes a string option the package does not have: mypy must refuse it (the options are
Literal types), as the library refuses it at run time."""

import isopatch

isopatch.mesh("torus", quality="fastest")
