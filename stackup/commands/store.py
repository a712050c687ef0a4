"""``stackup store check`` and ``stackup store repair``: a study's Zarr store read whole, and mended."""

from __future__ import annotations

from ._options import EXIT_DAMAGED, Formatter


def add_parser(subparsers):
    """Add ``store`` (with ``check`` and ``repair``) to the ``stackup`` subcommands; return its parser."""
    store = subparsers.add_parser("store", formatter_class=Formatter, help="check or repair a study's Zarr store",
                                  description="A study streamed into a Zarr store (Study(store=PATH)) can be checked "
                                  "for chunks that cannot be read, and repaired: the study chunks that wrote them are "
                                  "marked to be computed again, and running the same study with the same store "
                                  "recomputes them and keeps the rest.")
    actions = store.add_subparsers(dest="action", required=True, metavar="ACTION", help="what to do with the store")
    chk = actions.add_parser("check", formatter_class=Formatter, help="read every chunk; exit 1 if any is damaged",
                             description="Say what the store holds and read every chunk once; list the damaged "
                             "ones with the variable, the file, the engines and the recovery. Exit 0 if sound, 1 if "
                             "damaged.")
    chk.add_argument("path", metavar="PATH", help="the store (a folder)")
    chk.set_defaults(func=run_check)
    rep = actions.add_parser("repair", formatter_class=Formatter, help="mark damaged chunks to be computed again",
                             description="Mark the study chunks that wrote a damaged chunk to be computed again "
                             "(their files stay until rewritten, so nothing reads as zeros), rewrite damaged engine "
                             "numbers and drop a damaged running total of summaries; then run the same study with "
                             "the same store.")
    rep.add_argument("path", metavar="PATH", help="the store (a folder)")
    rep.set_defaults(func=run_repair)
    return store


def run_check(args, state):
    """Read every chunk of the store; print what it holds and each damaged chunk with its recovery."""
    from ..study.damage import check, status

    state.saved = "nothing was changed"
    print(_status(args.path, status(args.path)))
    damages = check(args.path)
    if not damages:
        print("Every chunk was read: no damage found.")
        return 0
    print(f"{len(damages)} damaged chunk{'s' if len(damages) > 1 else ''}:")
    for damage in damages:
        print(f"  {damage.where()}: {damage.error}")
    for remedy in dict.fromkeys(d.remedy(args.path) for d in damages):
        print(f"To recover: {remedy}.")
    return EXIT_DAMAGED


def run_repair(args, state):
    """Mark the damaged chunks to be computed again; print what was done and what to run next."""
    from ..study.damage import repair

    state.saved = f"the repair may be partial: run `stackup store repair {args.path}` again"
    damages = repair(args.path)
    if not damages:
        print(f"{args.path}: every chunk was read, no damage found; nothing to repair.")
        return 0
    for damage in damages:
        done = (f"study chunk {damage.study_chunk:06d} marked to be computed again" if damage.recovery == "recompute"
                else {"coordinate": "engine numbers rewritten",
                      "restart": "saved running total dropped"}.get(damage.recovery, "left as it is"))
        print(f"  {damage.where()}: {done}")
    kinds = {d.recovery for d in damages}
    if kinds & {"recompute", "restart", "rerun"}:
        print(f"Now run the same study with store={args.path!r} again: it computes what was marked and keeps the "
              "rest.")
    if "none" in kinds:
        print("This store was saved whole, not streamed by a study: save the dataset again.")
    return 0


def _status(path, st):
    if st.study is None:
        held = "complete" if st.finished else "no dataset attributes"
        return f"{path}: a Zarr store not streamed by a study ({held})"
    s = st.study
    kept = "every engine kept" if s.get("keep") == "everything" else "streaming summaries"
    text = f"{path}: a study of {s['n_engines']:,} engines x {len(s['schemes'])} schemes ({kept}); "
    if st.chunks_total is not None and st.chunks_done == st.chunks_total and st.finished:
        return text + f"all {st.chunks_total} chunks computed."
    of = f" of {st.chunks_total}" if st.chunks_total is not None else ""
    return text + (f"{st.chunks_done}{of} chunks computed; running the same study with store={path!r} computes "
                   "the rest and keeps these.")
