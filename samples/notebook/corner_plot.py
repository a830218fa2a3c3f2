#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Corner plot and predictive band of an admitgen fit, from the files beside fit.json.

Usage: corner_plot.py OUT/fit.json FIGURE_DIR [--order QxSy]

Reads fit.json -> "posterior" (posterior.json, schema admitgen.posterior/1), the equally weighted samples
of the selected order (or --order) from posterior_QxSy.csv, and predictive.csv. Writes
FIGURE_DIR/corner.png (800 x 800 px: histograms on the diagonal, the samples with the 2-sigma ellipse of
the posterior covariance below it) and FIGURE_DIR/predictive.png (800 x 450 px: the absorption of the
data with the posterior median and 95 % band). Debian: python3-numpy, python3-matplotlib.
The same lines work in a notebook cell; drop matplotlib.use("Agg") there.
"""
import argparse
import json
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load_posterior(fit_path, order=None):
    """Returns (order name, parameter names, samples [draws x dim], mean, covariance, predictive table)."""
    fit_path = pathlib.Path(fit_path)
    fit = json.loads(fit_path.read_text())
    index = json.loads((fit_path.parent / fit["posterior"]).read_text())
    order = order or index["selected"]
    entry = next(o for o in index["orders"] if o["order"] == order)
    samples = np.loadtxt(fit_path.parent / entry["samples_csv"], delimiter=",", skiprows=1, ndmin=2)
    predictive = np.genfromtxt(fit_path.parent / index["predictive_csv"], delimiter=",", names=True)
    return (order, entry["parameters"], samples, np.array(entry["mean"]), np.array(entry["covariance"]),
            predictive)


def ellipse(mean, cov, sigmas=2.0, points=100):
    """Boundary of the 2-D region (x - m)^T C^-1 (x - m) = sigmas^2: m + sigmas * L [cos t, sin t], C = L L^T."""
    t = np.linspace(0.0, 2.0 * np.pi, points)
    chol = np.linalg.cholesky(cov + 1e-300 * np.eye(2))
    return mean[:, None] + sigmas * chol @ np.vstack([np.cos(t), np.sin(t)])


def corner(names, samples, mean, cov, title):
    dim = len(names)
    fig, axes = plt.subplots(dim, dim, figsize=(8, 8), dpi=100, squeeze=False)
    for i in range(dim):
        for j in range(dim):
            ax = axes[i, j]
            if j > i:
                ax.set_axis_off()
                continue
            if i == j:
                ax.hist(samples[:, i], bins=30, color="tab:blue", histtype="stepfilled", alpha=0.7)
                ax.axvline(mean[i], color="k", lw=0.8)
                ax.set_yticks([])
            else:
                ax.plot(samples[:, j], samples[:, i], ".", ms=1.5, color="tab:blue", alpha=0.4)
                sub = np.ix_([j, i], [j, i])
                e = ellipse(mean[[j, i]], cov[sub])
                ax.plot(e[0], e[1], color="k", lw=0.8)
            if i == dim - 1:
                ax.set_xlabel(names[j], fontsize=7)
            else:
                ax.set_xticklabels([])
            if j == 0 and i > 0:
                ax.set_ylabel(names[i], fontsize=7)
            elif j > 0:
                ax.set_yticklabels([])
            ax.tick_params(labelsize=5)
            ax.tick_params(axis="x", labelrotation=45)
    fig.suptitle(title, fontsize=9)
    return fig


def band(predictive, title):
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=100)
    f = predictive["f_hz"]
    ax.fill_between(f, predictive["alpha_lo95"], predictive["alpha_hi95"], color="tab:orange", alpha=0.35,
                    label="95 % posterior predictive band")
    ax.plot(f, predictive["alpha_median"], color="tab:orange", label="posterior median")
    ax.plot(f, predictive["alpha_data"], ".", ms=2, color="k", label="data")
    ax.set_xscale("log")
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("absorption coefficient (normal incidence)")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=8)
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("fit_json")
    parser.add_argument("figure_dir")
    parser.add_argument("--order", help="order to plot (default: the selected one)")
    args = parser.parse_args()
    order, names, samples, mean, cov, predictive = load_posterior(args.fit_json, args.order)
    out = pathlib.Path(args.figure_dir)
    out.mkdir(parents=True, exist_ok=True)
    title = f"{order}: {samples.shape[0]} equally weighted posterior samples"
    corner(names, samples, mean, cov, title).savefig(out / "corner.png")
    band(predictive, f"{order}: absorption, data and posterior predictive").savefig(out / "predictive.png")
    print(f"wrote {out / 'corner.png'} and {out / 'predictive.png'} ({order}, {samples.shape[0]} samples)")


if __name__ == "__main__":
    main()
