"""Shards on Dask distributed: ``--workers N`` (a local cluster of N processes) or ``--cluster ADDRESS``.

Each shard (:class:`.shard.Shard`) lives as a Dask actor on one worker, holding its part of the visited
set, its frontier and its engine's caches between levels; the coordinator (:func:`.search.explore_keys`)
calls every shard at once and routes the successor keys between them. Dask is an optional extra
(``pip install 'fatline-verify[dask]'``); without it, asking for workers is a one-line error.
"""

from __future__ import annotations

from types import TracebackType
from typing import Any

from ..errors import InvalidInput
from ..schedulers.base import TransitionSystem


def require_dask(what: str) -> None:
    """Refuse ``what`` (a flag and its value) when Dask distributed is not installed."""
    try:
        import distributed  # noqa: F401
    except ImportError:
        raise InvalidInput(
            f"{what}: needs Dask distributed; expected it installed (pip install 'fatline-verify[dask]')"
        ) from None


class Cluster:
    """A Dask client: on a new local cluster of ``workers`` processes, or connected to ``address``.
    Used as a context manager; the local cluster is shut down on exit."""

    def __init__(self, workers: int = 1, address: str | None = None) -> None:
        from distributed import Client, LocalCluster

        self.local = None
        if address is None:
            self.local = LocalCluster(  # type: ignore[no-untyped-call]
                n_workers=workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,
                silence_logs=40,
            )
            self.client = Client(self.local)  # type: ignore[no-untyped-call]
        else:
            try:
                self.client = Client(address, timeout=10)  # type: ignore[no-untyped-call]
            except OSError as exc:
                raise InvalidInput(
                    f"cluster={address!r}: cannot connect ({exc}); expected a Dask scheduler address"
                ) from None

    @property
    def workers(self) -> list[str]:
        return sorted(self.client.scheduler_info()["workers"])

    def shards(
        self, system: TransitionSystem, n: int, bound: tuple[int, int], engine: str, after_violation: str
    ) -> DaskShards:
        """One shard per worker, each pinned to its worker."""
        from .shard import Shard

        addresses = self.workers
        futures = [
            self.client.submit(
                Shard, system, n, bound, engine, i, len(addresses), after_violation, actor=True, workers=[a], pure=False
            )
            for i, a in enumerate(addresses)
        ]
        return DaskShards([f.result() for f in futures])

    def close(self) -> None:
        self.client.close()  # type: ignore[no-untyped-call]
        if self.local is not None:
            self.local.close()  # type: ignore[no-untyped-call]

    def __enter__(self) -> Cluster:
        return self

    def __exit__(self, et: type[BaseException] | None, ev: BaseException | None, tb: TracebackType | None) -> None:
        self.close()


class DaskShards:
    """Shards as Dask actors; :meth:`map` calls every shard at once and waits for all."""

    def __init__(self, actors: list[Any]) -> None:
        self.actors = actors

    @property
    def count(self) -> int:
        return len(self.actors)

    def map(self, method: str, args: list[tuple[Any, ...]]) -> list[Any]:
        futures = [getattr(actor, method)(*a) for actor, a in zip(self.actors, args, strict=True)]
        return [f.result() for f in futures]

    def call(self, index: int, method: str, args: tuple[Any, ...]) -> Any:
        """One shard's ``method``, waited for."""
        return getattr(self.actors[index], method)(*args).result()

    def close(self) -> None:
        self.actors = []


__all__ = ["Cluster", "DaskShards", "require_dask"]
