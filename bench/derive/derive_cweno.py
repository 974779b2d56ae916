#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Symbolic derivation of the constants hard-coded in Core/include/sltk/interp/Cweno*.h.

Thesis (Preda 2024) 3.3: CWENO / CWENOZ reconstruction from point values.
Local coordinate per axis t = (x - x_i) / h, cell nodes at t = 0, 1, stencil nodes
t = -1, 0, 1, 2. Polynomials are written in the tensor monomial basis
t^j (1D), t^j s^k (2D, x fastest), t^j s^k r^l (3D).

Prints:
  1. the 1D inverse Vandermonde matrices (data -> monomial coefficients):
     cubic on {-1,0,1,2}, parabolas on {-1,0,1} (left/low) and {0,1,2} (right/high);
  2. the 1D integrals I^a_{jj'} = int_0^1 (d^a t^j)(d^a t^j') dt, a = 0..3, from which
     the indicator (3.18)/(3.24) is assembled per axis at run time (they factorise);
  3. the 1D quadratic forms (3.19)/(3.20): A_Q, A_L, A_R (thesis prints them: checked);
  4. the 2D matrices of (3.25)/(3.26) for a uniform grid, in units of 1/dx^2. The
     Appendix (partly garbled in the text) prints M of (3.25) for Delta = sqrt(2) dx
     (the cell diameter, used by the code) but A_k, A_opt of (3.26) for Delta = dx:
     both are printed here; TestCweno.cxx checks the legible entries;
  5. (--taylor) Taylor expansions of the 1D/2D/3D indicators on smooth data about the
     cell centre, with Delta = the cell diameter: every OSC is O(h^2), OSC_opt - OSC_k
     is O(h^3), and tau of (3.22)/(3.27) and its 3D extension
     |8 OSC_opt - sum_k OSC_k| are O(h^4). In 1D (c_m = u^(m)(x_0) / m!) the printed
     expansion of OSC_L, u''^2 h^2 - u'' u''' h^3 + ..., is (3.21).

Run: /usr/bin/python3 bench/derive/derive_cweno.py [--taylor]
"""
import itertools
import random
import sys

import sympy as sp

t = sp.Symbol("t")
NODES_CUBIC = [-1, 0, 1, 2]
NODES_LOW = [-1, 0, 1]
NODES_HIGH = [0, 1, 2]


def inverse_vandermonde(nodes):
    """C such that coefficients z = C u for the interpolant sum_j z_j t^j of data u at nodes."""
    n = len(nodes)
    v = sp.Matrix(n, n, lambda i, j: sp.Integer(nodes[i]) ** j)
    return v.inv()


def derivative_integrals(degree=3):
    """I[a][j][k] = int_0^1 d^a(t^j) d^a(t^k) dt."""
    out = []
    for a in range(degree + 1):
        m = sp.zeros(degree + 1, degree + 1)
        for j in range(degree + 1):
            for k in range(degree + 1):
                m[j, k] = sp.integrate(sp.diff(t ** j, t, a) * sp.diff(t ** k, t, a), (t, 0, 1))
        out.append(m)
    return out


def indicator_form(dim, degree, spacing, delta):
    """Matrix M with OSC[P] = z^T M z for the tensor basis of given degree per axis:
    OSC = sum_{|alpha|>=2} Delta^(2|alpha|-2-D) int_cell (d^alpha P)^2 dV,
    (3.18) for D = 1, (3.24) for D = 2 (Delta = cell diameter), same scaling in 3D."""
    integ = derivative_integrals(3)
    delta = sp.sympify(delta)
    spacing = [sp.sympify(h) for h in spacing]
    basis = list(itertools.product(range(degree + 1), repeat=dim))  # x fastest below
    basis = [tuple(reversed(b)) for b in basis]
    n = len(basis)
    m = sp.zeros(n, n)
    for alpha in itertools.product(range(degree + 1), repeat=dim):
        if sum(alpha) < 2:
            continue
        c = delta ** (2 * sum(alpha) - 2 - dim)
        for a in range(dim):
            c *= spacing[a] ** (1 - 2 * alpha[a])
        for p, bp in enumerate(basis):
            for q, bq in enumerate(basis):
                v = c
                for a in range(dim):
                    v *= integ[alpha[a]][bp[a], bq[a]]
                m[p, q] += v
    return basis, m


def tensor_coefficient_map(dim, nodes_per_axis):
    """Matrix from stencil data (x fastest) to tensor monomial coefficients (x fastest)."""
    mats = [inverse_vandermonde(nodes) for nodes in nodes_per_axis]
    out = mats[0]
    for a in range(1, dim):
        out = sp.kronecker_product(mats[a], out)  # axis a slower
    return out


def embed_in_cubic_stencil(dim, nodes_per_axis):
    """Selection matrix from the 4^D stencil data to a sub-stencil's data (both x fastest)."""
    n_sub = [len(nodes) for nodes in nodes_per_axis]
    rows = 1
    for n in n_sub:
        rows *= n
    sel = sp.zeros(rows, 4 ** dim)
    for r in range(rows):
        rest, flat, stride = r, 0, 1
        for a in range(dim):
            flat += NODES_CUBIC.index(nodes_per_axis[a][rest % n_sub[a]]) * stride
            rest //= n_sub[a]
            stride *= 4
        sel[r, flat] = 1
    return sel


def data_form(dim, nodes_per_axis, m_full, degree):
    """A with OSC = U^T A U / h^2 (uniform grid, h = 1) for the polynomial on the sub-stencil."""
    coef = tensor_coefficient_map(dim, nodes_per_axis)
    sel = embed_in_cubic_stencil(dim, nodes_per_axis)
    full = coef * sel
    basis = [tuple(reversed(b)) for b in itertools.product(range(degree + 1), repeat=dim)]
    big = [tuple(reversed(b)) for b in itertools.product(range(4), repeat=dim)]
    rows = [big.index(b) for b in basis]
    m = m_full.extract(rows, rows)
    return sp.simplify(full.T * m * full)


def print_matrix(name, m):
    print(name + " =")
    for i in range(m.rows):
        print("  [" + ", ".join(str(m[i, j]) for j in range(m.cols)) + "]")


def taylor_indicators(dim):
    """Indicators of the optimal and of the 2^D low-order polynomials on a smooth
    function, expanded in h about the cell centre (uniform grid, Delta = sqrt(D) h)."""
    h = sp.Symbol("h", positive=True)
    xs = sp.symbols("x0:%d" % dim)
    # generic smooth function: polynomial of total degree 5 about the cell centre, with
    # symbolic coefficients in 1D and random rational ones in 2D/3D (symbolic ones
    # make the 3D expansion too slow; the powers of h are the same for generic data)
    monos = [m for m in itertools.product(range(6), repeat=dim) if sum(m) <= 5]
    rng = random.Random(2024)
    coeffs = {m: (sp.Symbol("c_" + "".join(map(str, m))) if dim == 1
                  else sp.Rational(rng.randint(-9, 9), rng.randint(1, 9))) for m in monos}
    u = sum(coeffs[m] * sp.prod([(xs[a] - sp.Rational(1, 2) * h) ** m[a] for a in range(dim)]) for m in monos)
    # so derivatives at the cell centre (h/2, ..., h/2) are c_m * m!
    _, m_full = indicator_form(dim, 3, [1] * dim, sp.sqrt(dim))
    big = [tuple(reversed(b)) for b in itertools.product(range(4), repeat=dim)]

    def osc(nodes_per_axis, degree):
        grid = list(itertools.product(*[list(nodes) for nodes in reversed(nodes_per_axis)]))
        grid = [tuple(reversed(g)) for g in grid]
        data = sp.Matrix([u.subs({xs[a]: g[a] * h for a in range(dim)}) for g in grid])
        z = tensor_coefficient_map(dim, nodes_per_axis) * data
        basis = [tuple(reversed(b)) for b in itertools.product(range(degree + 1), repeat=dim)]
        rows = [big.index(b) for b in basis]
        m = m_full.extract(rows, rows)
        return sp.expand((z.T * m * z)[0, 0] / h ** 2)

    o_opt = osc([NODES_CUBIC] * dim, 3)
    lows = []
    for mask in range(2 ** dim):
        nodes = [NODES_HIGH if (mask >> a) & 1 else NODES_LOW for a in range(dim)]
        lows.append(osc(nodes, 2))
    tau = sp.expand(2 ** dim * o_opt - sum(lows))

    def order(e):
        e = sp.Poly(e, h)
        return min(mon[0] for mon in e.monoms()) if not e.is_zero else None

    print("D = %d: lowest power of h in OSC_opt: %s, in each OSC_k: %s, in tau: %s"
          % (dim, order(o_opt), [order(o) for o in lows], order(tau)))
    print("   OSC_opt - OSC_k lowest power: %s" % [order(sp.expand(o_opt - o)) for o in lows])
    if dim == 1:
        print("   OSC_L =", sp.collect(sp.expand(sp.series(lows[0], h, 0, 5).removeO()), h))


def main():
    print("# 1D inverse Vandermonde matrices (rows: coefficient of t^j, columns: data)")
    print_matrix("C_cubic {-1,0,1,2}", inverse_vandermonde(NODES_CUBIC))
    print_matrix("C_low {-1,0,1}", inverse_vandermonde(NODES_LOW))
    print_matrix("C_high {0,1,2}", inverse_vandermonde(NODES_HIGH))
    print("\n# 1D derivative integrals I^a_{jk} = int_0^1 d^a t^j d^a t^k dt")
    for a, m in enumerate(derivative_integrals(3)):
        print_matrix("I^%d" % a, m)

    print("\n# 1D indicator (3.18): OSC = z^T M z / dx^2, and data forms (3.20)")
    _, m1 = indicator_form(1, 3, [1], 1)
    print_matrix("M (1D)", m1)
    print_matrix("A_Q", data_form(1, [NODES_CUBIC], m1, 3))
    print_matrix("A_L", data_form(1, [NODES_LOW], m1, 2))
    print_matrix("A_R", data_form(1, [NODES_HIGH], m1, 2))

    print("\n# 2D indicator (3.24)-(3.26), uniform grid, Delta = sqrt(2) dx, units 1/dx^2")
    basis, m2 = indicator_form(2, 3, [1, 1], sp.sqrt(2))
    print("basis (powers of x, y), x fastest:", basis)
    print_matrix("M (2D, tensor order)", m2)
    b3 = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (3, 0), (2, 1), (1, 2), (0, 3),
          (3, 1), (2, 2), (1, 3), (3, 2), (2, 3), (3, 3)]
    perm = [basis.index(b) for b in b3]
    print_matrix("M (2D, thesis basis B_3 order)", m2.extract(perm, perm))
    # The Appendix prints A_k and A_opt computed with Delta = dx (its M of (3.25) uses
    # the diameter): print both; CwenoInterpolator uses the diameter (Documentation/Numerics.md).
    for label, delta in (("Delta = sqrt(2) dx", sp.sqrt(2)), ("Delta = dx, as in the Appendix", 1)):
        print("\n## data forms (3.26), U ordered x fastest over the 4x4 stencil, " + label)
        _, m = indicator_form(2, 3, [1, 1], delta)
        print_matrix("A_sw", data_form(2, [NODES_LOW, NODES_LOW], m, 2))
        print_matrix("A_se", data_form(2, [NODES_HIGH, NODES_LOW], m, 2))
        print_matrix("A_nw", data_form(2, [NODES_LOW, NODES_HIGH], m, 2))
        print_matrix("A_ne", data_form(2, [NODES_HIGH, NODES_HIGH], m, 2))
        print_matrix("A_opt", data_form(2, [NODES_CUBIC, NODES_CUBIC], m, 3))

    if "--taylor" in sys.argv:
        print("\n# Taylor expansions of the indicators about the cell centre")
        for dim in (1, 2, 3):
            taylor_indicators(dim)


if __name__ == "__main__":
    main()
