"""Studies streamed into a Zarr store: identical numbers, out of core, resumable."""

import pickle

import numpy as np
import pytest
import xarray as xr
import zarr

import stackup.study.chain as chain_module
import stackup.study.sinks as sinks_module
from stackup.study.store import ChunkStore, open_study, to_stored
from stackup.study import Study


def small(engine, **kw):
    return Study(**{"engine": str(engine), "n_engines": 200, "seed": 5, "pilot_engines": 2000, "progress": False,
                    "chunk_lots": 1, **kw})


@pytest.mark.integration
def test_a_stored_study_is_identical_and_opened_lazily(engine_file, tmp_path):
    kw = dict(mechanics_engines=12, crank_angle_step=12.0, history=True)
    engine = engine_file(lot=40)
    reference = small(engine, **kw).run()
    stored = small(engine, **kw, store=str(tmp_path / "s.zarr")).run()
    assert stored.clearance_operating.chunks is not None  # dask-backed: read on use
    assert list(stored.data_vars) == list(reference.data_vars)
    xr.testing.assert_identical(stored.load(), reference)
    xr.testing.assert_identical(open_study(tmp_path / "s.zarr").load(), reference)


@pytest.mark.integration
def test_summaries_are_stored_and_resumed_identically(engine_file, tmp_path):
    engine = engine_file(lot=40)
    reference = small(engine, keep="summaries", mechanics_engines=0).run()
    store = str(tmp_path / "s.zarr")
    xr.testing.assert_identical(small(engine, keep="summaries", mechanics_engines=0, store=store).run(), reference)
    xr.testing.assert_identical(open_study(store).load(), reference)
    xr.testing.assert_identical(small(engine, keep="summaries", mechanics_engines=0, store=store).run(), reference)


def _fail_in_third_chunk(monkeypatch):
    calls = {"n": 0}
    real = chain_module.assemble

    def failing(*args, **kwargs):
        calls["n"] += 1
        if calls["n"] > 6 * 2:  # six schemes per chunk: die in the third chunk
            raise KeyboardInterrupt("power cut")
        return real(*args, **kwargs)

    monkeypatch.setattr(chain_module, "assemble", failing)
    return calls


@pytest.mark.integration
@pytest.mark.parametrize("keep", ["everything", "summaries"])
def test_interrupted_study_resumes_without_losing_or_repeating_chunks(engine_file, tmp_path, monkeypatch, keep):
    engine = engine_file(lot=40)
    kw = dict(keep=keep, mechanics_engines=0 if keep == "summaries" else 200, crank_angle_step=24.0)
    reference = small(engine, **kw).run()
    calls = _fail_in_third_chunk(monkeypatch)
    monkeypatch.setattr(sinks_module, "SUMMARY_CHECKPOINT_SECONDS", 0.0)  # save the running total every chunk
    interrupted = small(engine, **kw, store=str(tmp_path / "s.zarr"))
    with pytest.raises(KeyboardInterrupt):
        interrupted.run()
    book = zarr.open_group(str(tmp_path / "s.zarr"), mode="r")["chunks"]
    if keep == "everything":
        assert sorted(name for name, g in book.groups() if g.attrs["complete"]) == ["000000", "000001"]
    else:
        assert book.attrs["total"]["next"] == 2  # the saved total holds chunks 0 and 1

    calls["n"] = -10**9  # no more failures; count the chunks computed on resume
    resumed = pickle.loads(pickle.dumps(interrupted)).run()
    assert calls["n"] == -10**9 + 6 * 3  # only chunks 2, 3 and 4 were computed
    xr.testing.assert_identical(resumed.load(), reference)


@pytest.mark.integration
def test_target_error_resumes_from_the_store_with_the_same_decision(tmp_path, monkeypatch):
    from importlib.resources import files

    text = (files("stackup") / "data" / "engines" / "iso-example.toml").read_text()
    engine = tmp_path / "example-lots-of-50.toml"
    engine.write_text(text.replace("lot_engines = 1000", "lot_engines = 50"))
    kw = dict(engine=str(engine), n_engines=300, schemes=("iso13778-4",), crank_angle_step=12.0,
              mechanics_engines=150, pilot_engines=2000, progress=False, chunk_lots=1)
    # a target the mean film reaches between 75 and 100 engines, whatever the film model gives
    h_min = Study(**kw).run().h_min.values
    errors = [chain_module._film_error(h_min[:, :n], None) for n in (75, 100)]
    kw["target_error"] = float(np.mean(errors)) if errors[1] < errors[0] else errors[1]
    reference = Study(**kw).run()
    used = reference.attrs["mechanics_engines_used"]
    assert 50 < used < 150  # the decision needs the films of earlier chunks
    real = chain_module.engine_cycles
    calls = {"n": 0}

    def failing(*args, **kwargs):
        calls["n"] += 1
        if calls["n"] > 2:  # two batches of 25 engines: die in the second chunk
            raise KeyboardInterrupt("power cut")
        return real(*args, **kwargs)

    monkeypatch.setattr(chain_module, "engine_cycles", failing)
    store = str(tmp_path / "t.zarr")
    with pytest.raises(KeyboardInterrupt):
        Study(**kw, store=store).run()
    monkeypatch.setattr(chain_module, "engine_cycles", real)
    resumed = Study(**kw, store=store).run()
    assert resumed.attrs["mechanics_engines_used"] == used
    xr.testing.assert_identical(resumed.load(), reference)


def test_a_store_of_another_study_is_refused(engine_file, tmp_path):
    store = str(tmp_path / "s.zarr")
    small(engine_file(), n_engines=60, store=store).run()
    with pytest.raises(ValueError, match="store: .* holds chunks of another study"):
        small(engine_file(), n_engines=61, store=store).run()


def test_a_zarr_group_that_is_not_a_study_is_refused(tmp_path):
    group = zarr.open_group(str(tmp_path / "other.zarr"), mode="w")
    group.create_array("x", shape=(3,), dtype="f8")
    with pytest.raises(ValueError, match="store: .* holds data that is not a stackup study"):
        ChunkStore(tmp_path / "other.zarr", "{}")


def test_labels_are_coded_and_an_unknown_label_is_named():
    ds = xr.Dataset({"grade": ("e", np.array(["A", "", "C"]))})
    stored = to_stored(ds, {"A", "B", "C"})
    assert stored.grade.dtype == np.int8
    assert stored.grade.attrs["stackup_labels"] == ["", "A", "B", "C"]
    with pytest.raises(ValueError, match="grade: label 'C' is not one of"):
        to_stored(ds, {"A"})


@pytest.mark.integration
def test_memory_of_a_study_kept_in_a_store_does_not_grow_with_n(engine_file, tmp_path):
    import tracemalloc

    engine = engine_file(lot=500)

    def peak(n):
        tracemalloc.start()
        small(engine, n_engines=n, mechanics_engines=0, store=str(tmp_path / f"{n}.zarr")).run()
        value = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        return value

    peak(1000)  # warm caches
    assert peak(16000) < 1.3 * peak(4000)
