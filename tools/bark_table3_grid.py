#!/usr/bin/env python3
"""tools/bark_table3_grid.py — summarises tools/bark_table3_grid.sh's rows (stdin): per shared
setting, how many of hirota1998 Table 3's twelve numbers it meets as table03 judges them (each
mean within 20 % of the paper's, each max within 30 %, camphor's max height over 20 cm: its
'(>20)'; the views' max, averaged over the seeds), and whether the means come in the paper's
order (widths camphor < tallow < pine, heights camphor > pine > tallow). Markdown on stdout."""
import sys

# Table 3, simulated column (width, height in cm): mean and max; camphor's max height '(>20)'.
PAPER_MEAN = [(1.58, 11.6), (1.70, 3.02), (2.34, 4.28)]
PAPER_MAX = [(2.06, None), (2.08, 3.96), (3.24, 6.48)]
SPECIES = ["camphor", "tallow", "pine"]


def pair(cell):
    w, h = cell.split(" x ")
    return float(w), float(h)


def parse(line):
    """'<seeds> | D .. | cw x ch | tw x th | pw x ph | t/c | views' max x 3 |'."""
    seeds, rest = line.split(" ", 1)
    cells = [c.strip() for c in rest.strip().strip("|").split("|")]
    if len(cells) != 8:
        raise ValueError("bark_table3_grid.py: expected 8 cells in: " + line.strip())
    name = cells[0].replace(" kappa-1 x1.000", "")  # the grid keeps Table 2's kappas
    return {"seeds": int(seeds), "name": name, "mean": [pair(c) for c in cells[1:4]],
            "max": [pair(c) for c in cells[5:8]]}


def judge(row):
    """The numbers met (of 12), the ratios, the order."""
    met, ratios = 0, []
    for i in range(3):
        for k in range(2):
            r = row["mean"][i][k] / PAPER_MEAN[i][k]
            ratios.append(r)
            met += abs(r - 1) <= 0.2
        for k in range(2):
            paper = PAPER_MAX[i][k]
            ours = row["max"][i][k]
            if paper is None:
                met += ours > 20.0
                ratios.append(None)
            else:
                ratios.append(ours / paper)
                met += abs(ours / paper - 1) <= 0.3
    (cw, ch), (tw, th), (pw, ph) = row["mean"]
    width_order = cw < tw < pw
    height_order = ch > ph > th
    return met, ratios, width_order, height_order


def main():
    rows = list({(r["name"], r["seeds"]): r
                 for r in (parse(l) for l in sys.stdin if l.strip())}.values())
    if not rows:
        sys.exit("bark_table3_grid.py: no rows on stdin")
    judged = [(judge(r), r) for r in rows]
    judged.sort(key=lambda jr: (-jr[0][0], jr[1]["name"]))
    hist = {}
    for (met, _, _, _), _ in judged:
        hist[met] = hist.get(met, 0) + 1
    all_means = [r for (m, ratios, _, _), r in judged
                 if all(abs(ratios[i * 4 + k] - 1) <= 0.2 for i in range(3) for k in range(2))]
    max_h_both = [r for (m, ratios, _, _), r in judged
                  if abs(ratios[7] - 1) <= 0.3 and abs(ratios[11] - 1) <= 0.3]
    width_order = sum(1 for (m, _, w, _), _ in judged if w)
    ratio_tc = max(r["mean"][1][0] / r["mean"][0][0] for _, r in judged)
    # the same where camphor keeps Table 3's strips: its mean height within 20 %
    strips = [r for (m, ratios, _, _), r in judged if abs(ratios[1] - 1) <= 0.2]
    ratio_strips = max(r["mean"][1][0] / r["mean"][0][0] for r in strips) if strips else 0
    print("%d shared settings (Table 2 as printed). Numbers of Table 3 met (of 12): %s." % (
        len(rows), ", ".join("%d in %d" % (k, hist[k]) for k in sorted(hist, reverse=True))))
    print("All six means within 20 %%: %d (%s). Both max heights (tallow, pine) within 30 %%: %d."
          " Widths in the paper's order: %d. Largest tallow / camphor mean width: %.2f (%.2f where"
          " camphor's mean height is within 20 %%).\n" % (
              len(all_means), "; ".join("%s, %d seeds" % (r["name"], r["seeds"])
                                        for r in all_means) or "none",
              len(max_h_both), width_order, ratio_tc, ratio_strips))
    print("| setting | seeds | met | means / paper (camphor w h, tallow w h, pine w h) | "
          "max / paper (camphor w, tallow w h, pine w h) | camphor max h | order w / h |")
    print("|---|---|---|---|---|---|---|")
    for (met, ratios, w, h), r in judged:
        means = " ".join("%.2f" % ratios[i * 4 + k] for i in range(3) for k in range(2))
        maxes = " ".join("%.2f" % ratios[i * 4 + 2 + k] for i in range(3) for k in range(2)
                         if ratios[i * 4 + 2 + k] is not None)
        print("| %s | %d | %d | %s | %s | %.2f | %s / %s |" % (
            r["name"], r["seeds"], met, means, maxes, r["max"][0][1], "yes" if w else "no",
            "yes" if h else "no"))


if __name__ == "__main__":
    main()
