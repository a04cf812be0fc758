#!/usr/bin/env python3
"""tools/bark_table3_grid.py — summarises tools/bark_table3_grid.sh's rows (stdin): per shared
setting, how many of hirota1998 Table 3's twelve numbers it meets as table03 judges them (each
mean within 20 % of the paper's, each max within 30 %, camphor's max height over 20 cm in every
seed: its '(>20)'), and whether the means come in the paper's order (widths camphor < tallow <
pine, heights camphor > pine > tallow). A setting run over 3 and over 5 seeds is judged on its
5-seed row. Markdown on stdout."""
import sys

# Table 3, simulated column (width, height in cm): mean and max; camphor's max height '(>20)'.
PAPER_MEAN = [(1.58, 11.6), (1.70, 3.02), (2.34, 4.28)]
PAPER_MAX = [(2.06, None), (2.08, 3.96), (3.24, 6.48)]


def pair(cell):
    w, h = cell.split(" x ")
    return float(w), float(h)


def parse(line):
    """'<seeds> | D .. | cw x ch | tw x th | pw x ph | t/c | views' max x 3 | camphor lo |'."""
    seeds, rest = line.split(" ", 1)
    cells = [c.strip() for c in rest.strip().strip("|").split("|")]
    if len(cells) != 9:
        sys.exit("bark_table3_grid.py: expected 9 cells in: " + line.strip())
    name = cells[0].replace(" kappa-1 x1.000", "")  # the grid keeps Table 2's kappas
    return {"seeds": int(seeds), "name": name, "mean": [pair(c) for c in cells[1:4]],
            "max": [pair(c) for c in cells[5:8]], "camphor_lo": float(cells[8])}


def judge(row):
    """The numbers met (of 12), the ratios (None for camphor's '(>20)'), the two orders."""
    met, ratios = 0, []
    for i in range(3):
        for k in range(2):
            r = row["mean"][i][k] / PAPER_MEAN[i][k]
            ratios.append(r)
            met += abs(r - 1) <= 0.2
        for k in range(2):
            paper = PAPER_MAX[i][k]
            if paper is None:
                met += row["camphor_lo"] > 20.0
                ratios.append(None)
            else:
                ratios.append(row["max"][i][k] / paper)
                met += abs(ratios[-1] - 1) <= 0.3
    (cw, ch), (tw, th), (pw, ph) = row["mean"]
    return met, ratios, cw < tw < pw, ch > ph > th


def main():
    rows = {}
    for line in sys.stdin:
        if line.strip():
            r = parse(line)
            if r["name"] not in rows or r["seeds"] > rows[r["name"]]["seeds"]:
                rows[r["name"]] = r
    if not rows:
        sys.exit("bark_table3_grid.py: no rows on stdin")
    judged = sorted(((judge(r), r) for r in rows.values()),
                    key=lambda jr: (-jr[0][0], jr[1]["name"], jr[1]["seeds"]))
    hist = {}
    for (met, _, _, _), _ in judged:
        hist[met] = hist.get(met, 0) + 1
    def within(ratios, i, tol):
        return abs(ratios[i] - 1) <= tol
    all_means = [r for (_, ratios, _, _), r in judged
                 if all(within(ratios, i * 4 + k, 0.2) for i in range(3) for k in range(2))]
    tallow_max_h = sum(1 for (_, ratios, _, _), _ in judged if within(ratios, 7, 0.3))
    pine_max_h = sum(1 for (_, ratios, _, _), _ in judged if within(ratios, 11, 0.3))
    both_max_h = sum(1 for (_, ratios, _, _), _ in judged
                     if within(ratios, 7, 0.3) and within(ratios, 11, 0.3))
    width_order = sum(1 for (_, _, w, _), _ in judged if w)
    ratio_tc = max(r["mean"][1][0] / r["mean"][0][0] for _, r in judged)
    # the same where camphor keeps Table 3's strips: its mean height within 20 %
    strips = [r for (_, ratios, _, _), r in judged if within(ratios, 1, 0.2)]
    ratio_strips = max(r["mean"][1][0] / r["mean"][0][0] for r in strips) if strips else 0
    print("%d shared settings (Table 2 as printed; %d over 5 seeds, the rest over 3). Numbers of "
          "Table 3 met (of 12): %s." % (
              len(rows), sum(1 for r in rows.values() if r["seeds"] == 5),
              ", ".join("%d in %d" % (k, hist[k]) for k in sorted(hist, reverse=True))))
    print("All six means within 20 %%: %d (%s). Max height within 30 %%: tallow's in %d, pine's "
          "in %d, both in %d. Widths in the paper's order: %d. Largest tallow / camphor mean "
          "width: %.2f (%.2f where camphor's mean height is within 20 %%).\n" % (
              len(all_means), "; ".join("%s, %d seeds" % (r["name"], r["seeds"])
                                        for r in all_means) or "none",
              tallow_max_h, pine_max_h, both_max_h, width_order, ratio_tc, ratio_strips))
    print("| setting | seeds | met | means / paper (camphor w h, tallow w h, pine w h) | "
          "max / paper (camphor w, tallow w h, pine w h) | camphor max h, smallest seed | "
          "order w / h |")
    print("|---|---|---|---|---|---|---|")
    for (met, ratios, w, h), r in judged:
        means = " ".join("%.3f" % ratios[i * 4 + k] for i in range(3) for k in range(2))
        maxes = " ".join("%.3f" % x for x in (ratios[2], ratios[6], ratios[7], ratios[10],
                                              ratios[11]))
        print("| %s | %d | %d | %s | %s | %.2f | %s / %s |" % (
            r["name"], r["seeds"], met, means, maxes, r["camphor_lo"], "yes" if w else "no",
            "yes" if h else "no"))


if __name__ == "__main__":
    main()
