"""The exceptions isopatch raises: one class per kind of library error, with the library's message.

Every class derives from :class:`Error`; those about bad input also derive from the built-in exception
a Python user would catch for it (``ValueError``, ``LookupError``, ``OSError``, ``ArithmeticError``).
"""

from __future__ import annotations


class Error(Exception):
    """Base of every isopatch error. ``setting`` names the argument the error is about ('' if none);
    ``command_line_message`` is the message in the command line's words (its flags where ``message``
    names keyword arguments), for front ends that run as a command."""

    def __init__(self, message: str, setting: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.setting = setting
        self.command_line_message = message

    def __str__(self) -> str:
        return self.message


class InternalError(Error):
    """A bug in isopatch: an invariant did not hold. Please report it with the input."""


class InputError(Error, ValueError):
    """An argument out of its documented range (a bad box, a negative edge length, a malformed array)."""


class SettingError(InputError):
    """An InputError about one setting, named by ``setting`` (e.g. 'edge_length', 'threads')."""


class UnknownSurfaceError(Error, LookupError):
    """A name that is not in the catalogue; the message suggests the closest one."""


class ParseError(Error, ValueError):
    """A malformed formula. ``line`` and ``column`` are 1-based; ``excerpt`` shows the place with a caret."""

    def __init__(self, message: str, line: int = 0, column: int = 0, excerpt: str = "") -> None:
        super().__init__(message)
        self.line = line
        self.column = column
        self.excerpt = excerpt


class IoError(Error, OSError):
    """A file that cannot be read or written, or a malformed file; the message names the file."""

    def __init__(self, message: str, setting: str = "") -> None:
        Error.__init__(self, message, setting)
        self.args = (message,)


class EvaluationError(Error, ArithmeticError):
    """f returned NaN or infinity at a point the mesher needed (the message names the point)."""


class NoSurfaceError(Error):
    """f = 0 does not cross the box (or no sample of a volume crosses the level)."""


class LimitError(Error):
    """A budget (max_vertices, max_evaluations, time_limit) ran out; ``setting`` names it."""


class SingularSurfaceError(Error):
    """grad f vanishes on f = 0 (a repeated factor such as g**3): there is no gradient to mesh with."""


class CreaseError(Error):
    """The faces of a CSG shape meet in a way no mesh can follow (solids touching along an edge, a
    sheet of zero thickness, a crease that cannot be traced)."""


__all__ = [
    "Error",
    "InternalError",
    "InputError",
    "SettingError",
    "UnknownSurfaceError",
    "ParseError",
    "IoError",
    "EvaluationError",
    "NoSurfaceError",
    "LimitError",
    "SingularSurfaceError",
    "CreaseError",
]
