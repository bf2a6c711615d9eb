"""Run calls in fresh processes, a few at a time, killing them at once on interrupt.

z3's answers (and times) depend on the terms a process created before, so the prover runs every
obligation in its own process: each answer is independent of the others and of the order.

Each process is forked from a fork server (``multiprocessing``'s ``forkserver``) that has imported the
prover (:data:`PRELOAD`) and done nothing else: no z3 term, no z3 context (z3 makes its context on
first use), one thread. A process forked from it starts in the state a freshly spawned interpreter
reaches after the same imports, without paying for them on every obligation (spawn: 1.7 to 2.4 s of
interpreter start and imports per obligation, against solving times of 0.0 to 0.5 s for most;
``python bench/prove.py --startup 10``). Where there is no fork server (not POSIX), spawn.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import multiprocessing.connection
import signal
import threading
import time
from collections.abc import Callable, Iterator
from multiprocessing.connection import Connection
from typing import Any, cast

Call = tuple[Callable[..., Any], tuple[Any, ...], dict[str, Any]]

PRELOAD = ("fatline_verify.prove.search", "fatline_verify.prove.family", "fatline_verify.prove.prover")
"""What the fork server imports once: every module an obligation's call needs (none of them creates a
z3 context or a thread at import; ``tests/test_fresh.py`` checks that a call finds none)."""


def _context() -> Any:
    """The fork server (preloaded with :data:`PRELOAD`), or spawn where there is none."""
    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn")
    ctx = multiprocessing.get_context("forkserver")
    ctx.set_forkserver_preload(list(PRELOAD))  # read when the server starts: on the first call only
    return ctx


def _child(conn: Any, fn: Callable[..., Any], args: tuple[Any, ...], kwargs: dict[str, Any]) -> None:
    """A fresh process's one task: its answer (or its exception) goes back through ``conn``.
    SIGINT is ignored: an interrupt is the parent's to handle, and the parent kills the workers."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        answer: tuple[bool, Any] = (True, fn(*args, **kwargs))
    except Exception as exc:  # sent to the parent, which raises it there
        answer = (False, exc)
    try:
        conn.send(answer)
    except OSError:  # the parent is gone (interrupted while it read this answer): no one to tell
        return
    except Exception as exc:  # an unpicklable answer or exception
        with contextlib.suppress(OSError):
            conn.send((False, RuntimeError(f"{fn.__name__}: {exc.__class__.__name__}: {exc}")))
    conn.close()


@contextlib.contextmanager
def _interrupt_after() -> Iterator[None]:
    """Hold an interrupt (SIGINT) back until the block is done: a process interrupted halfway through
    its start gets no task to read and prints a traceback, and so does the fork server; started
    whole, it is killed with the rest. (Python runs signal handlers in the main thread, whichever
    thread the signal reached, so swapping the handler holds it back where a signal mask might not.)"""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    held: list[int] = []
    previous = signal.signal(signal.SIGINT, lambda signum, _: held.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        if held and callable(previous):
            previous(signal.SIGINT, None)  # Python's own raises KeyboardInterrupt here


def run_fresh(
    calls: list[Call],
    workers: int,
    done: Callable[[int, Any], None],
    *,
    limit: float | Callable[[int], float | None] | None = None,
    overrun: Callable[[int, float], Any] | None = None,
    on_start: Callable[[int], None] | None = None,
) -> None:
    """Run each call in a new process (forked from the fork server, see the module docstring), at most
    ``workers`` at once; ``done(k, answer)`` as each finishes. z3's answers depend on the terms a
    process created before, so one process per call makes every answer independent of the others and
    of the order.

    ``limit``: wall-clock seconds after which a call's process is killed and ``done(k, overrun(k,
    seconds))`` reports it instead (a solver can ignore its own limits: z3 was seen in one integer
    check for over half an hour under a budget of 84 s); or a function of ``k`` giving each call's
    (``None``: none). Without ``overrun`` there is no limit.
    ``on_start(k)``: call ``k``'s process has started (for progress: the seconds spent on it so far).

    An interrupt (or any error) kills every running worker at once and propagates: nothing waits for
    a solver to finish. (``ProcessPoolExecutor`` cannot promise that: after ``shutdown`` its manager
    thread waits for work it has already queued, and interpreter exit waits for the manager.)
    """
    ctx = _context()
    pending = list(enumerate(calls))[::-1]
    running: dict[Any, tuple[int, Any]] = {}
    started: dict[int, float] = {}

    def guard(k: int) -> float | None:
        if overrun is None:
            return None
        return limit(k) if callable(limit) else limit

    try:
        while pending or running:
            while pending and len(running) < workers:
                k, (fn, args, kwargs) = pending.pop()
                receive, send = ctx.Pipe(duplex=False)
                proc = ctx.Process(target=_child, args=(send, fn, args, kwargs), daemon=True)
                with _interrupt_after():  # a process is started whole, then killed below if need be
                    proc.start()
                    started[k] = time.monotonic()
                    send.close()
                    running[receive] = (k, proc)
                if on_start is not None:
                    on_start(k)
            ends = [started[k] + g for k, _ in running.values() if (g := guard(k)) is not None]
            wait = max(0.0, min(ends) - time.monotonic()) if ends else None
            ready_now = multiprocessing.connection.wait(list(running), timeout=wait)
            if overrun is not None:
                for conn, (k, proc) in list(running.items()):
                    elapsed = time.monotonic() - started[k]
                    g = guard(k)
                    if conn not in ready_now and g is not None and elapsed >= g:
                        running.pop(conn)
                        proc.kill()
                        proc.join(timeout=5)
                        conn.close()
                        done(k, overrun(k, elapsed))
            for ready in ready_now:
                conn = cast(Connection, ready)
                k, proc = running[conn]  # still running (killed below if interrupted) until read whole
                try:
                    ok, answer = conn.recv()
                except EOFError:
                    ok, answer = False, RuntimeError(f"a worker process died (exit code {proc.exitcode})")
                del running[conn]
                conn.close()
                proc.join()
                if not ok:
                    raise answer if isinstance(answer, BaseException) else RuntimeError(str(answer))
                done(k, answer)
    finally:
        for conn, (_, proc) in running.items():
            proc.kill()
            proc.join(timeout=5)
            conn.close()


def isolated(fn: Callable[..., Any], *args: Any, **kwargs: Any) -> Any:
    """Run one call in a fresh process, as ``fatline prove`` does, and return its answer."""
    answers: list[Any] = []
    run_fresh([(fn, args, kwargs)], 1, lambda _, answer: answers.append(answer))
    return answers[0]


__all__ = ["Call", "isolated", "run_fresh"]
