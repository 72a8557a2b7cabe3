"""The exceptions relgeo raises: one class per kind of relgeo::Error (C++),
carrying relgeo's message and its ``code`` (``"invalid_input"``,
``"non_finite_coordinate"``, ...; include/relgeo/core/errors.h).

Bad input is a ``ValueError`` (so ``except ValueError`` works as for numpy),
and a file that cannot be read or written an ``OSError`` as well. A wrong
kernel, algorithm or operation name raises a plain ``ValueError``.
"""

import numpy.linalg


class Error(Exception):
    """Base of every exception relgeo::Error becomes (relgeo::Error)."""

    code = "computation_failure"


class InvalidInput(Error, ValueError):
    """Input that no algorithm of relgeo accepts (relgeo::Invalid_input)."""

    code = "invalid_input"


class NonFiniteInput(InvalidInput):
    """A coordinate is NaN or infinite (relgeo::Non_finite_input)."""

    code = "non_finite_coordinate"


class UnreadableFile(InvalidInput, OSError):
    """A file cannot be opened or parsed (relgeo::Unreadable_file, io::Parse_error)."""

    code = "unreadable_file"


class UnwritableFile(InvalidInput, OSError):
    """A file cannot be written (relgeo::io::Unwritable_file)."""

    code = "invalid_input"


class InvalidMesh(InvalidInput):
    """A mesh violates a requirement: index out of range, not a closed solid,
    self-intersecting Boolean operand... (relgeo::Invalid_mesh)."""


class InvalidOperand(InvalidMesh):
    """A Boolean operand does not bound a solid: open, non-manifold,
    misoriented, degenerate or self-intersecting (relgeo::Invalid_operand)."""


class InvalidCsgNode(InvalidInput):
    """A CSG tree that cannot be evaluated (relgeo::Invalid_csg_node): an
    unknown op, fewer than two arguments, a leaf that cannot be read or is
    not a valid solid. ``node`` is the node's path: "root", "root.1" (root's
    second argument), ..."""

    node = None


class PreconditionViolation(Error, ValueError):
    """The call broke a documented precondition (relgeo::Precondition_violation)."""

    code = "precondition_violation"


class SingularMatrix(Error, ValueError, numpy.linalg.LinAlgError):
    """An exactly singular matrix (relgeo::Singular_matrix; ``code`` is
    ``"invalid_input"``): bad input, and numpy's LinAlgError as well."""


__all__ = ["Error", "InvalidInput", "NonFiniteInput", "UnreadableFile", "UnwritableFile",
           "InvalidMesh", "InvalidOperand", "InvalidCsgNode", "PreconditionViolation", "SingularMatrix"]
