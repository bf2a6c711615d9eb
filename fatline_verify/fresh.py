"""Run calls in fresh interpreters (spawn), a few at a time, killing them at once on interrupt.

z3's answers (and times) depend on the terms a process created before, so the prover runs every
obligation in its own process: each answer is independent of the others and of the order.
"""

from __future__ import annotations

import multiprocessing
import multiprocessing.connection
import signal
import time
from collections.abc import Callable
from multiprocessing.connection import Connection
from typing import Any, cast

Call = tuple[Callable[..., Any], tuple[Any, ...], dict[str, Any]]


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
    except Exception as exc:  # an unpicklable answer or exception
        conn.send((False, RuntimeError(f"{fn.__name__}: {exc.__class__.__name__}: {exc}")))
    conn.close()


def run_fresh(
    calls: list[Call],
    workers: int,
    done: Callable[[int, Any], None],
    *,
    limit: float | None = None,
    overrun: Callable[[int, float], Any] | None = None,
) -> None:
    """Run each call in a new interpreter (spawn), at most ``workers`` at once; ``done(k, answer)``
    as each finishes. z3's answers depend on the terms a process created before, so one process per
    call makes every answer independent of the others and of the order.

    ``limit``: wall-clock seconds after which a call's process is killed and ``done(k, overrun(k,
    seconds))`` reports it instead (a solver can ignore its own limits: z3 was seen in one integer
    check for over half an hour under a budget of 84 s). Without ``overrun`` there is no limit.

    An interrupt (or any error) kills every running worker at once and propagates: nothing waits for
    a solver to finish. (``ProcessPoolExecutor`` cannot promise that: after ``shutdown`` its manager
    thread waits for work it has already queued, and interpreter exit waits for the manager.)
    """
    ctx = multiprocessing.get_context("spawn")
    pending = list(enumerate(calls))[::-1]
    running: dict[Any, tuple[int, Any]] = {}
    started: dict[int, float] = {}
    guard = limit if overrun is not None else None
    try:
        while pending or running:
            while pending and len(running) < workers:
                k, (fn, args, kwargs) = pending.pop()
                receive, send = ctx.Pipe(duplex=False)
                proc = ctx.Process(target=_child, args=(send, fn, args, kwargs), daemon=True)
                proc.start()
                started[k] = time.monotonic()
                send.close()
                running[receive] = (k, proc)
            wait = (
                None
                if guard is None
                else max(0.0, min(started[k] + guard for k, _ in running.values()) - time.monotonic())
            )
            ready_now = multiprocessing.connection.wait(list(running), timeout=wait)
            if guard is not None and overrun is not None:
                for conn, (k, proc) in list(running.items()):
                    elapsed = time.monotonic() - started[k]
                    if conn not in ready_now and elapsed >= guard:
                        running.pop(conn)
                        proc.kill()
                        proc.join(timeout=5)
                        conn.close()
                        done(k, overrun(k, elapsed))
            for ready in ready_now:
                conn = cast(Connection, ready)
                k, proc = running.pop(conn)
                try:
                    ok, answer = conn.recv()
                except EOFError:
                    ok, answer = False, RuntimeError(f"a worker process died (exit code {proc.exitcode})")
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
