"""Shared pieces of the independent implementation."""


class DomainError(Exception):
    """A rule's precondition is violated (spec: the C++ DomainError)."""


def require(cond, msg):
    if not cond:
        raise DomainError(msg)
