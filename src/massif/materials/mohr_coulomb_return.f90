!> Return map of perfectly plastic Mohr–Coulomb in principal stresses (tension positive),
!> with non-associated flow and an optional tension cut-off.
!>
!> With sigma_1 >= sigma_2 >= sigma_3 the yield planes met by a return are
!>   F13 = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi)   (main plane)
!>   F23, F12 (same form on the pairs (2,3), (1,2): the edges s1 = s2 and s2 = s3)
!>   T_i = s_i - t  (tension cut-off, when t is below the apex c cot(phi)),
!> with plastic potentials G_ij of the same form with psi, and T_i associated. All are
!> linear in the principal stresses, so for a set J of active surfaces the implicit return
!>   s = s_trial - De B dgamma,  A^T s = r_J   (A, B: gradients of f and g, De: elasticity)
!> is one small linear solve, and its derivative is
!>   d s / d s_trial = I - De B (A^T De B)^-1 A^T.
!> The active set is the smallest one (main plane, then the edges, then corners) whose
!> multipliers are >= 0 and whose stress violates no yield plane (Koiter's conditions).
!> Beyond the apex a non-associated flow (psi < phi) cannot restore the mean stress, no set
!> qualifies, and the stress goes to the apex (tangent 0), as in de Souza Neto et al. (2008);
!> below a tension cut-off the associated return is used instead.
module pecplas_massif_materials_mohr_coulomb_return
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, run_error
   use pecplas_massif_materials_soil, only: soil_params_t, RETURN_ELASTIC, RETURN_APEX
   implicit none (type, external)
   private

   public :: mohr_coulomb_return, mohr_coulomb_yield

contains

   !> Largest value of the yield functions (the six Mohr–Coulomb planes and, when t is
   !> below the apex, the cut-off) at principal stresses `s` (any order). Scaled as stress.
   pure real(wp) function mohr_coulomb_yield(soil, tension, s) result(f)
      type(soil_params_t), intent(in) :: soil
      real(wp), intent(in) :: tension, s(3)
      f = (maxval(s) - minval(s)) + (maxval(s) + minval(s))*sin(soil%phi) &
         - 2.0_wp*soil%cohesion*cos(soil%phi)
      if (tension < apex_stress(soil)) f = max(f, maxval(s) - tension)
   end function mohr_coulomb_yield

   !> Returns principal stresses `values` from `trial` (same labels, any order) and
   !> `dvalues` = d values / d trial; `kind` is RETURN_ELASTIC or the number of active
   !> surfaces (RETURN_SMOOTH, RETURN_EDGE, RETURN_APEX). `tension` is the cut-off t
   !> (huge for none).
   subroutine mohr_coulomb_return(soil, tension, trial, values, dvalues, kind, error)
      type(soil_params_t), intent(in) :: soil
      real(wp), intent(in) :: tension, trial(3)
      real(wp), intent(out) :: values(3), dvalues(3, 3)
      integer, intent(out) :: kind
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: a(3, 6), b(3, 6), r(6), s(3), p(3, 3), sig(3)
      integer :: order(3), n, i, j
      logical :: found, cutoff

      order = descending(trial)
      s = trial(order)
      cutoff = tension < apex_stress(soil)
      call surfaces(soil, soil%psi, tension, cutoff, a, b, r, n)
      dvalues = 0.0_wp
      do i = 1, 3
         dvalues(i, i) = 1.0_wp
      end do
      values = trial
      kind = RETURN_ELASTIC
      if (all(matmul(s, a(:, 1:n)) - r(1:n) <= 0.0_wp)) return

      call find_active_set(soil, tension, a(:, 1:n), b(:, 1:n), r(1:n), s, sig, p, kind, found)
      if (.not. found) then
         if (.not. cutoff .and. soil%phi > 0.0_wp) then
            sig = apex_stress(soil)
            p = 0.0_wp
            kind = RETURN_APEX
            found = .true.
         else
            ! associated (closest point in the energy norm): a convex problem, always solvable
            call find_active_set(soil, tension, a(:, 1:n), a(:, 1:n), r(1:n), s, sig, p, &
               kind, found)
         end if
      end if
      if (.not. found) then
         call run_error(error, 'Mohr-Coulomb return found no admissible stress')
         return
      end if
      ! back to the labels of `trial`
      do i = 1, 3
         values(order(i)) = sig(i)
         do j = 1, 3
            dvalues(order(i), order(j)) = p(i, j)
         end do
      end do
   end subroutine mohr_coulomb_return

   !> Apex of the cone, c cot(phi) on each principal stress (huge for phi = 0).
   pure real(wp) function apex_stress(soil)
      type(soil_params_t), intent(in) :: soil
      apex_stress = huge(1.0_wp)
      if (soil%phi > 0.0_wp) apex_stress = soil%cohesion/tan(soil%phi)
   end function apex_stress

   !> Gradients a (yield), b (potential with dilatancy `psi`) and constants r of the
   !> surfaces met by a return in the ordered sector: F13, F23, F12 [, T1, T2, T3].
   pure subroutine surfaces(soil, psi, tension, cutoff, a, b, r, n)
      type(soil_params_t), intent(in) :: soil
      real(wp), intent(in) :: psi, tension
      logical, intent(in) :: cutoff
      real(wp), intent(out) :: a(3, 6), b(3, 6), r(6)
      integer, intent(out) :: n
      integer, parameter :: pairs(2, 3) = reshape([1, 3, 2, 3, 1, 2], [2, 3])
      real(wp) :: sp, sq
      integer :: k
      sp = sin(soil%phi); sq = sin(psi)
      a = 0.0_wp; b = 0.0_wp
      do k = 1, 3
         a(pairs(1, k), k) = 1.0_wp + sp
         a(pairs(2, k), k) = -(1.0_wp - sp)
         b(pairs(1, k), k) = 1.0_wp + sq
         b(pairs(2, k), k) = -(1.0_wp - sq)
         r(k) = 2.0_wp*soil%cohesion*cos(soil%phi)
      end do
      n = 3
      if (cutoff) then
         do k = 1, 3
            a(k, 3 + k) = 1.0_wp
            b(k, 3 + k) = 1.0_wp
            r(3 + k) = tension
         end do
         n = 6
      end if
   end subroutine surfaces

   !> Tries the active sets by size (1, 2, 3), each in lexicographic order; accepts the first
   !> with non-negative multipliers whose stress is admissible.
   pure subroutine find_active_set(soil, tension, a, b, r, s, sig, p, kind, found)
      type(soil_params_t), intent(in) :: soil
      real(wp), intent(in) :: tension, a(:, :), b(:, :), r(:), s(3)
      real(wp), intent(out) :: sig(3), p(3, 3)
      integer, intent(out) :: kind
      logical, intent(out) :: found
      real(wp) :: de(3, 3), scale
      integer :: n, i, j, k
      n = size(r)
      de = soil%lambda
      do i = 1, 3
         de(i, i) = soil%lambda + 2.0_wp*soil%shear
      end do
      scale = max(maxval(abs(s)), soil%cohesion, tiny(1.0_wp))
      found = .false.
      do i = 1, n
         call solve_set(soil, tension, de, a(:, [i]), b(:, [i]), r([i]), s, scale, sig, p, &
            kind, found)
         if (found) return
      end do
      do i = 1, n
         do j = i + 1, n
            call solve_set(soil, tension, de, a(:, [i, j]), b(:, [i, j]), r([i, j]), s, scale, &
               sig, p, kind, found)
            if (found) return
         end do
      end do
      do i = 1, n
         do j = i + 1, n
            do k = j + 1, n
               call solve_set(soil, tension, de, a(:, [i, j, k]), b(:, [i, j, k]), r([i, j, k]), &
                  s, scale, sig, p, kind, found)
               if (found) return
            end do
         end do
      end do
   end subroutine find_active_set

   !> Return with the surfaces (a, b, r) all active: `found` when the set is independent,
   !> its multipliers are >= 0 and the stress violates no yield plane.
   pure subroutine solve_set(soil, tension, de, a, b, r, s, scale, sig, p, kind, found)
      type(soil_params_t), intent(in) :: soil
      real(wp), intent(in) :: tension, de(3, 3), a(:, :), b(:, :), r(:), s(3), scale
      real(wp), intent(out) :: sig(3), p(3, 3)
      integer, intent(out) :: kind
      logical, intent(out) :: found
      real(wp) :: g(size(r), size(r)), ginv(size(r), size(r)), dg(size(r)), deb(3, size(r))
      logical :: ok
      integer :: q
      found = .false.
      sig = s; p = 0.0_wp; kind = 0
      deb = matmul(de, b)
      g = matmul(transpose(a), deb)
      call invert(g, ginv, ok)
      if (.not. ok) return
      dg = matmul(ginv, matmul(s, a) - r)
      if (any(dg < -1.0e-10_wp*maxval(abs(dg)))) return
      sig = s - matmul(deb, dg)
      if (mohr_coulomb_yield(soil, tension, sig) > 1.0e-10_wp*scale) return
      p = -matmul(deb, matmul(ginv, transpose(a)))
      do q = 1, 3
         p(q, q) = p(q, q) + 1.0_wp
      end do
      kind = size(r)
      found = .true.
   end subroutine solve_set

   !> Inverse of a small matrix by Gauss–Jordan with partial pivoting; `ok` false when a
   !> pivot is negligible (dependent surfaces, e.g. parallel planes for phi = 0).
   pure subroutine invert(g, ginv, ok)
      real(wp), intent(in) :: g(:, :)
      real(wp), intent(out) :: ginv(:, :)
      logical, intent(out) :: ok
      real(wp) :: w(size(g, 1), 2*size(g, 1)), row(2*size(g, 1)), big
      integer :: m, i, k
      m = size(g, 1)
      w = 0.0_wp
      w(:, 1:m) = g
      do i = 1, m
         w(i, m + i) = 1.0_wp
      end do
      big = maxval(abs(g))
      ok = .false.
      do i = 1, m
         k = i - 1 + maxloc(abs(w(i:m, i)), 1)
         if (.not. (abs(w(k, i)) > 1.0e-12_wp*big)) return
         row = w(k, :); w(k, :) = w(i, :); w(i, :) = row
         w(i, :) = w(i, :)/w(i, i)
         do k = 1, m
            if (k /= i) w(k, :) = w(k, :) - w(k, i)*w(i, :)
         end do
      end do
      ginv = w(:, m + 1:2*m)
      ok = .true.
   end subroutine invert

   !> Indices that sort `x` in decreasing order (stable: equal values keep their order).
   pure function descending(x) result(idx)
      real(wp), intent(in) :: x(3)
      integer :: idx(3), i, j, t
      idx = [1, 2, 3]
      do i = 2, 3
         j = i
         do while (j > 1)
            if (.not. (x(idx(j)) > x(idx(j - 1)))) exit
            t = idx(j); idx(j) = idx(j - 1); idx(j - 1) = t
            j = j - 1
         end do
      end do
   end function descending

end module pecplas_massif_materials_mohr_coulomb_return
