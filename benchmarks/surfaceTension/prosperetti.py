#!/usr/bin/env python3
"""prosperetti.py: the amplitude of a small capillary wave between two
fluids of equal density and kinematic viscosity, Prosperetti (1981)'s
initial-value solution (no gravity, infinite depth):

    a(t)/a0 = sum_i z_i/Z_i omega0^2/(z_i^2 - nu k^2)
              exp((z_i^2 - nu k^2) t) erfc(z_i sqrt(t))

z_i the roots of z^4 - s z^3 - s^2 z^2 + s^3 z + omega0^2 = 0 (s = k
sqrt(nu)), Z_i = prod_{j != i} (z_j - z_i), omega0^2 = sigma k^3/(2 rho).

Module: amplitude(t, k, nu, sigma, rho).  Run: prints a(t)/a0 for Popinet
(2009)'s case (lambda 1, rho 1, sigma 1, La 3000) at t = 0 ... 2.2.
"""
import cmath
import math


def erfcx(z):
    """exp(z^2) erfc(z) for complex z"""
    if abs(z) < 3.0:
        # erf by its Taylor series
        s, term, n = 0j, z, 0
        while True:
            add = term/(2*n + 1)
            s += add
            if abs(add) <= 1e-17*abs(s) or n > 300:
                break
            n += 1
            term *= -z*z/n
        return cmath.exp(z*z)*(1 - 2/math.sqrt(math.pi)*s)
    if z.real < 0:
        return 2*cmath.exp(z*z) - erfcx(-z)
    # Laplace's continued fraction, from the tail
    f = 0j
    for n in range(200, 0, -1):
        f = (n/2)/(z + f)
    return 1/(math.sqrt(math.pi)*(z + f))


def roots(c):
    """The four roots of z^4 + c[0] z^3 + c[1] z^2 + c[2] z + c[3]"""
    z = [complex(0.4, 0.9)**k for k in range(4)]
    for _ in range(2000):
        new = []
        for i, zi in enumerate(z):
            p = zi**4 + c[0]*zi**3 + c[1]*zi**2 + c[2]*zi + c[3]
            q = 1
            for j, zj in enumerate(z):
                if j != i:
                    q *= zi - zj
            new.append(zi - p/q)
        if max(abs(a - b) for a, b in zip(new, z)) < 1e-15:
            z = new
            break
        z = new
    return z


def amplitude(t, k, nu, sigma, rho):
    w02 = sigma*k**3/(2*rho)
    s = k*math.sqrt(nu)
    z = roots([-s, -s*s, s**3, w02])
    a = 0j
    for i, zi in enumerate(z):
        Z = 1
        for j, zj in enumerate(z):
            if j != i:
                Z *= zj - zi
        x = zi*math.sqrt(t)
        a += zi/Z*w02/(zi*zi - nu*k*k)*cmath.exp(-nu*k*k*t)*erfcx(x)
    return a.real


if __name__ == "__main__":
    k, rho, sigma = 2*math.pi, 1.0, 1.0
    nu = math.sqrt(sigma*1.0/(3000*rho))/rho     # La = sigma rho lambda/mu^2
    for i in range(12):
        t = 0.2*i
        print(f"{t:.2f} {amplitude(t, k, nu, sigma, rho):.6f}")
