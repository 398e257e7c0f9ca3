# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""The compiled part of the module (python/native_module.cpp): the command line's commands run in
process as typed commands (``simulate``, ``orbit``, ``family``, ``modes``, ``map``, ``merge``, ``report``, ``stability``, ``glo_set``, ``bar``, ``info``). Not for direct use: the functions of
``grazelab`` call it."""

from typing import Callable, List, Optional, Tuple

import numpy as np

version: str

class Refused(ValueError):
    """A typed command's refusal (its one line)."""

class NotWritten(OSError):
    """A file a typed command could not write (its one line)."""

def simulate(options: tuple, result_type: type, events: bool = ...,
             max_events: int = ..., discard_events: bool = ..., direct: bool = ...
             ) -> Optional[Tuple[dict, Optional[List[str]]]]: ...

def family(options: List[Tuple[str, Optional[str]]], result_type: type,
           progress: Optional[Callable[[Optional[float], str], None]] = ...) -> Tuple[dict, np.ndarray]: ...

def modes(options: List[Tuple[str, Optional[str]]], result_type: type,
          progress: Optional[Callable[[Optional[float], str], None]] = ...) -> Tuple[dict, List[np.ndarray]]: ...

def impacts_family(options: List[Tuple[str, Optional[str]]], result_type: type,
                   progress: Optional[Callable[[Optional[float], str], None]] = ...) -> Tuple[dict, List[np.ndarray]]: ...

def map(options: List[Tuple[str, Optional[str]]], result_type: type,
        progress: Optional[Callable[[Optional[float], str], None]] = ...) -> Tuple[dict, np.ndarray]: ...

def merge(parts: List[str], out: Optional[str], result_type: type) -> Tuple[dict, np.ndarray]: ...

def report(options: List[Tuple[str, Optional[str]]],
           progress: Optional[Callable[[Optional[float], str], None]] = ...) -> Tuple[bytes, str, str]: ...

def stability(options: List[Tuple[str, Optional[str]]],
              progress: Optional[Callable[[Optional[float], str], None]] = ...) -> Tuple[bytes, str, str]: ...

def orbit(options: List[Tuple[str, Optional[str]]], result_type: type) -> dict: ...

def glo_set(options: List[Tuple[str, Optional[str]]], result_type: type) -> dict: ...

def bar(options: List[Tuple[str, Optional[str]]], result_type: type) -> dict: ...

def info(options: List[Tuple[str, Optional[str]]], result_type: type) -> dict: ...

class PreparedChain:
    """A chain of N masses read, checked and designed once (use grazelab.Chain)."""
    period: float
    def describe(self, result_type: type) -> dict: ...

def prepare_chain(options: List[str]) -> PreparedChain: ...

def simulate_chain(chain: PreparedChain, options: tuple, result_type: type, discard_events: bool = ...,
                   direct: bool = ..., max_events: int = ...) -> Optional[Tuple[dict, Optional[List[str]]]]: ...
