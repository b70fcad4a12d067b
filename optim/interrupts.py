"""Ctrl-C that reaches the caller, even through a solver that swallows it.

CasADi checks for Ctrl-C while IPOPT runs, turns Python's ``KeyboardInterrupt`` into a
C++ exception and returns a failed solve (``NonIpopt_Exception_Thrown``): a sweep
would record the point as failed and carry on. The command line therefore installs
:func:`sigint_handler` (:func:`catching_interrupts`), which notes the interrupt
before raising ``KeyboardInterrupt``, and every solve calls
:func:`raise_if_interrupted` after IPOPT returns.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator
from typing import Any

_PENDING = {"interrupt": False}


def sigint_handler(signum: int, frame: Any) -> None:
    """SIGINT handler: note the interrupt, then raise ``KeyboardInterrupt`` as Python's
    default handler does.

    Parameters
    ----------
    signum : int
        The signal number [-].
    frame : frame or None
        The interrupted frame [-].

    Returns
    -------
    None
        Never returns normally.

    Raises
    ------
    KeyboardInterrupt
        Always.
    """
    _PENDING["interrupt"] = True
    raise KeyboardInterrupt


def raise_if_interrupted() -> None:
    """Raise ``KeyboardInterrupt`` if Ctrl-C came (and was swallowed) since the last call.

    Called after each IPOPT solve; a no-op unless :func:`sigint_handler` is installed
    (unit [-]).

    Raises
    ------
    KeyboardInterrupt
        An interrupt is pending.
    """
    if _PENDING["interrupt"]:
        _PENDING["interrupt"] = False
        raise KeyboardInterrupt


def interrupt_pending() -> bool:
    """Whether Ctrl-C came and has not been raised again yet.

    Returns
    -------
    bool
        True between :func:`sigint_handler` and :func:`raise_if_interrupted` [-].
    """
    return _PENDING["interrupt"]


@contextlib.contextmanager
def catching_interrupts() -> Iterator[None]:
    """Install :func:`sigint_handler` while inside (main thread only, and only where Ctrl-C
    is not ignored, as in a background job); the previous handler is restored.

    Returns
    -------
    context manager
        Yields nothing [-].
    """
    previous = None
    if (threading.current_thread() is threading.main_thread()
            and signal.getsignal(signal.SIGINT) is signal.default_int_handler):
        previous = signal.signal(signal.SIGINT, sigint_handler)
    _PENDING["interrupt"] = False
    try:
        yield
    finally:
        _PENDING["interrupt"] = False
        if previous is not None:
            signal.signal(signal.SIGINT, previous)


__all__ = ["catching_interrupts", "interrupt_pending", "raise_if_interrupted",
           "sigint_handler"]
