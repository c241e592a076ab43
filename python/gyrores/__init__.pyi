# Type stubs of the package gyrores (PEP 561: py.typed beside them). The signatures are those
# of gyrores/__init__.py; python/tests/test_signatures.py compares them, and docs/python.md's list.
from decimal import Decimal
from fractions import Fraction
from os import PathLike
from typing import Any, Callable, Iterable, Iterator, Optional, SupportsIndex, Tuple, Union

import mpmath
import numpy as np
import numpy.typing as npt

from ._types import Interval as Interval, Result as Result

__version__: str

Real = Union[float, mpmath.mpf]
Rational = Union[SupportsIndex, float, Fraction, Decimal, mpmath.mpf, str]
Integers = Union[npt.NDArray[np.integer], Iterable[SupportsIndex]]

class UsageError(ValueError): ...
class ComputeError(ArithmeticError): ...

class PairResult(Result):
    tau: int
    sigma: int
    r_res: Real
    h_min: Real
    theta_first: Real
    t_first: Real
    minimisers: Tuple[Real, ...]
    digits: int
    # Computed on first access (pair() leaves them out of the first computation), same values:
    asymptotic: Result
    r_res_asy: Optional[Real]
    r_res_asy_rel_error: Optional[Real]
    bits: int
    def to_dict(self, raw: bool = ...) -> dict: ...

class CheckResult(Result):
    holds: bool
    failure: str
    def __bool__(self) -> bool: ...

def pair(tau: SupportsIndex, sigma: SupportsIndex, digits: SupportsIndex = 17, qdot0: Rational = 1,
         enclosures: bool = False) -> PairResult: ...
def pairs(taus: Integers, sigmas: Integers, digits: Optional[SupportsIndex] = None, certified: bool = False,
          checks: str = "default",
          threads: SupportsIndex = 0) -> np.ndarray: ...
def asymptotics(tau: SupportsIndex, sigma: SupportsIndex, digits: SupportsIndex = 17) -> Result: ...
def certify(tau: SupportsIndex, sigma: SupportsIndex, digits: SupportsIndex = 30) -> dict: ...
def check(cert: Union[dict, str, PathLike]) -> CheckResult: ...
def design(problem: str, tmax: Rational, beat: Optional[Rational] = None, max_order: SupportsIndex = 200,
           exclude_low: SupportsIndex = 0, delta: Optional[SupportsIndex] = None, proxy: bool = False,
           candidates: SupportsIndex = 5, digits: SupportsIndex = 10, tolerance: Optional[Rational] = None,
           level: Optional[Rational] = None, horizon: Optional[Rational] = None) -> Result: ...
def pareto(max_order: SupportsIndex, orientation: str = "absorb", proxy: bool = False,
           exclude_degenerate: bool = False, beat: Optional[Rational] = None, exclude_low: SupportsIndex = 0,
           digits: SupportsIndex = 10) -> Result: ...
def plant(mass: Rational, stiffness: Rational, gyro: Rational, velocity: Rational,
          digits: SupportsIndex = 17) -> Result: ...
def coupling(n: Optional[Rational] = None, n2: Optional[Rational] = None, horizon: Optional[Rational] = None,
             below: Optional[Rational] = None, convergents: SupportsIndex = 8, digits: SupportsIndex = 12,
             band: Optional[Union[Tuple[Rational, Rational], str]] = None, tolerance: Optional[Rational] = None,
             band_digits: Optional[SupportsIndex] = None, qdot0: Rational = 1,
             pair: Optional[Tuple[SupportsIndex, SupportsIndex]] = None, plant: Optional[Any] = None,
             horizon_s: Optional[Rational] = None) -> Result: ...
def couplings(n: Optional[Union[Rational, npt.ArrayLike]] = None, n2: Optional[Union[Rational, npt.ArrayLike]] = None,
              horizon: Union[Rational, npt.ArrayLike] = 100, below: Optional[Rational] = None,
              progress: Optional[Callable[[int, int], Any]] = None) -> np.ndarray: ...
def enumerate_pairs(max_order: SupportsIndex, min_order: SupportsIndex = 3) -> Iterator[Tuple[int, int]]: ...
def sweep(max_order: SupportsIndex, min_order: SupportsIndex = 3, rows: bool = True,
          progress: Optional[Callable[[int, int], Any]] = None, checks: str = "default", threads: SupportsIndex = 0,
          examples: SupportsIndex = 5, allow_large: bool = False) -> Tuple[Optional[np.ndarray], Result]: ...
