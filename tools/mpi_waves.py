#!/usr/bin/env python3
"""Where each rank's time went in a render shared among processes, wave by wave, from wardray's --stats file.

For each wave: its tiles and records, then per rank the wall milliseconds in its share of the tiles, in the exchange
(waiting for the slowest rank, then the transfer) and in merging the records. The totals then split what the render
loses against a perfect split of the same processor time:
- one-tile waves: a wave of fewer tiles than ranks keeps the others waiting, whatever the schedule;
- the rest of the waiting: tiles of uneven cost within a wave (at most the last tile's cost with tiles drawn as ranks
  become free);
- the merge, which every rank makes in full (serial, as in one process).
Last, the critical path in processor time and its excess over an even split, the figure to compare between builds
on a loaded machine.

usage: tools/mpi_waves.py STATS.json [--waves]      (--waves: one line per wave as well as the totals)
"""
import json
import sys


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        stats = json.load(f)
    processes = stats.get("processes")
    if not processes:
        print("no 'processes' in the stats: the render was not shared among ranks", file=sys.stderr)
        return 1
    waves = [w for w in processes["waves"] if w.get("ranks")]
    ranks = processes["count"]
    totals = [dict(busy=0.0, tiles=0.0, exchange=0.0, merge=0.0) for _ in range(ranks)]
    narrow_wait = 0.0  # waiting in waves of fewer tiles than ranks, over every rank
    if "--waves" in argv:
        print("wave tiles records | " + " | ".join(f"rank {r}: tiles exch merge (ms)" for r in range(ranks)))
    for i, w in enumerate(waves):
        cells = []
        for r, t in enumerate(w["ranks"]):
            for key, name in (("busy_cpu_seconds", "busy"), ("tiles_seconds", "tiles"),
                              ("exchange_seconds", "exchange"), ("merge_seconds", "merge")):
                totals[r][name] += t[key]
            if w["tiles"] < ranks:
                narrow_wait += t["exchange_seconds"]
            cells.append(f"{t['tiles_seconds'] * 1e3:7.1f} {t['exchange_seconds'] * 1e3:6.1f} "
                         f"{t['merge_seconds'] * 1e3:5.1f}")
        if "--waves" in argv:
            print(f"{i:4d} {w['tiles']:5d} {w['records']:7d} | " + " | ".join(cells))
    for r, t in enumerate(totals):
        print(f"rank {r}: busy {t['busy']:.3f} cpu s; wall: tiles {t['tiles']:.3f} s, exchanges {t['exchange']:.3f} s, "
              f"merges {t['merge']:.3f} s")
    mean_tiles = sum(t["tiles"] for t in totals) / ranks
    span = max(t["tiles"] + t["exchange"] + t["merge"] for t in totals)
    print(f"waves' span {span:.3f} s against the ranks' mean time in tiles {mean_tiles:.3f} s: "
          f"waiting {sum(t['exchange'] for t in totals) / ranks:.3f} s a rank "
          f"({narrow_wait / ranks:.3f} s of it in waves of fewer tiles than ranks), "
          f"merging {sum(t['merge'] for t in totals) / ranks:.3f} s a rank")
    # The same in processor time, which the machine's load moves far less than wall time: the sum over waves of the
    # busiest rank's time in its tiles, and how far it lies above half of all the ranks' time in tiles.
    critical = sum(w["busy_max_cpu_seconds"] for w in waves)
    busy = sum(t["busy"] for t in totals)
    print(f"critical path {critical:.3f} cpu s, {(critical - busy / ranks) * 1e3:.1f} ms over an even split of "
          f"all the ranks' {busy:.3f} cpu s in tiles")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
