"""The check of doc/build.md, "A compiler defect at -O3" (pecplas_py.checks.cond_reductions),
on the defect's own loop compiled by this machine's gfortran at -O3.

The forward search assigns k under two conditions; the backward search (the form the program
uses) stops at the first match. Both must return 2 for a = [2, 0, 0, 0, 0, 0, 0, 0] at every
n >= 1. Where the compiler gets the forward loop wrong (gfortran 12.2 at -O3 returns 1 from
n = 4 on), the check must list that loop; it must never list the backward one, whose answers
must be right."""
import shutil
import subprocess

import pytest

from pecplas_py.checks.cond_reductions import chained_loops

SOURCE = """module m
implicit none
contains
integer function forward(a, n) result(k)
   integer, intent(in) :: a(:), n
   integer :: i
   k = 1
   do i = 1, min(n, size(a))
      if (a(i) == -1) k = 0
      if (a(i) > 0) k = a(i)
   end do
end function forward
integer function backward(a, n) result(k)
   integer, intent(in) :: a(:), n
   integer :: i
   k = 1
   do i = min(n, size(a)), 1, -1
      if (a(i) == -1) then
         k = 0
         return
      end if
      if (a(i) > 0) then
         k = a(i)
         return
      end if
   end do
end function backward
end module m
program p
use m
implicit none
integer :: a(8), n
a = 0
a(1) = 2
do n = 1, 8
   print '(2i3)', forward(a, n), backward(a, n)
end do
end program p
"""


@pytest.mark.skipif(shutil.which("gfortran") is None, reason="needs gfortran")
def test_check_lists_the_miscompiled_loop(tmp_path):
    (tmp_path / "loops.f90").write_text(SOURCE)
    subprocess.run(["gfortran", "-O3", "-fdump-tree-vect-details", "loops.f90", "-o", "loops"],
                   cwd=tmp_path, check=True, capture_output=True)
    rows = [line.split() for line in subprocess.run(
        [str(tmp_path / "loops")], check=True, capture_output=True, text=True).stdout.splitlines()]
    assert len(rows) == 8
    assert all(b == "2" for _, b in rows), f"backward search wrong at -O3: {rows}"
    listed = chained_loops(sorted(tmp_path.glob("*.vect")))
    lines = {int(loc.rsplit(":", 1)[1]) for loc in listed}
    forward_line = SOURCE.splitlines().index("   do i = 1, min(n, size(a))") + 1
    assert lines <= {forward_line}, f"listed other loops than the forward search: {listed}"
    if any(f != "2" for f, _ in rows):
        assert forward_line in lines, f"forward search wrong at -O3 ({rows}) but not listed"
