!> Plastic hinges at the ends of a 2-node plate element (plane strain, NP and/or MP given):
!> the element's basic forces q = (N, Ma, Mb) (axial force, section moments at its first and
!> second node) follow from its basic deformations v = (elongation, -phi1, phi2) (phi_i the
!> end rotations from the chord) by the exact Timoshenko stiffness Kb less the plastic
!> deformations of its two end hinges: q = Kb (v - vp). Each end yields on
!> f_i = (N/Np)^2 + (M_i/Mp)^2 - 1 <= 0 with associated flow (vp += dl_i df_i/dq); the return
!> is the closest point in the metric of Kb^-1 with the active ends found by trial, and the
!> consistent tangent follows from the linearised return. A hinge forms exactly at a node,
!> so a collapse mechanism of hinges at nodes has its exact load (theory.md §12).
module pecplas_structures_hinge
   use pecplas_base_kinds, only: wp
   use pecplas_base_matrix3, only: inverse3
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_plates, only: plate_section_t
   use pecplas_structures_beam, only: shear_stiffness
   implicit none (type, external)
   private

   public :: hinge_gamma, hinge_stiffness, hinge_update

contains

   !> Gamma (3, 6): v = Gamma U for the global dofs (u_x, u_y, theta) of nodes x(:, 1:2).
   pure function hinge_gamma(x) result(g)
      real(wp), intent(in) :: x(:, :)
      real(wp) :: g(3, 6)
      real(wp) :: h, t(2), n(2)
      h = norm2(x(:, 2) - x(:, 1))
      t = (x(:, 2) - x(:, 1))/h
      n = [-t(2), t(1)]
      g = 0.0_wp
      g(1, 1:2) = -t
      g(1, 4:5) = t
      g(2, 1:2) = -n/h
      g(2, 3) = -1.0_wp
      g(2, 4:5) = n/h
      g(3, 1:2) = n/h
      g(3, 4:5) = -n/h
      g(3, 6) = 1.0_wp
   end function hinge_gamma

   !> Elastic basic stiffness Kb (3, 3) of an element of length h: EA'/h, and the exact
   !> Timoshenko bending block EI'/(h (1 + phi)) [4 + phi, -(2 - phi); -(2 - phi), 4 + phi],
   !> phi = 12 EI' / (GAs h^2) (EA' = EA/(1-nu^2), EI' = EI/(1-nu^2)).
   pure function hinge_stiffness(section, h) result(kb)
      type(plate_section_t), intent(in) :: section
      real(wp), intent(in) :: h
      real(wp) :: kb(3, 3)
      real(wp) :: d, phi, c
      d = section%ei/(1.0_wp - section%nu**2)
      phi = 12.0_wp*d/(shear_stiffness(section)*h**2)
      c = d/(h*(1.0_wp + phi))
      kb = 0.0_wp
      kb(1, 1) = section%ea/(1.0_wp - section%nu**2)/h
      kb(2, 2) = c*(4.0_wp + phi)
      kb(3, 3) = kb(2, 2)
      kb(2, 3) = -c*(2.0_wp - phi)
      kb(3, 2) = kb(2, 3)
   end function hinge_stiffness

   !> Basic forces q and plastic deformations vp at the basic deformations vp0 + ... :
   !> q = Kb (v - vp), from the converged plastic deformations vp0; dl(2) the multipliers of
   !> the step at the two ends, kalg (3, 3) the consistent tangent dq/dv.
   subroutine hinge_update(section, kb, v, vp0, q, vp, dl, kalg, error)
      type(plate_section_t), intent(in) :: section
      real(wp), intent(in) :: kb(3, 3), v(3), vp0(3)
      real(wp), intent(out) :: q(3), vp(3), dl(2), kalg(3, 3)
      type(error_t), allocatable, intent(out) :: error
      real(wp), parameter :: TOL = 1.0e-12_wp
      real(wp) :: ia, im, kinv(3, 3), r(5), jac(5, 5), dx(5), fv(2), rhs(5, 3), det
      logical :: active(2), changed
      integer :: it, pass, na, i, j, idx(2)
      ia = 0.0_wp
      im = 0.0_wp
      if (section%np > 0.0_wp) ia = 1.0_wp/section%np**2
      if (section%mp > 0.0_wp) im = 1.0_wp/section%mp**2
      call inverse3(kb, kinv, det)  ! kb: a plate's elastic section stiffness, regular
      q = matmul(kb, v - vp0)
      vp = vp0
      dl = 0.0_wp
      kalg = kb
      fv = yield(q)
      active = fv > TOL
      ! without Mp both ends yield on N alone: one constraint
      if (im == 0.0_wp) active(2) = .false.
      if (.not. any(active)) return
      do pass = 1, 6
         na = count(active)
         idx = 0
         j = 0
         do i = 1, 2
            if (active(i)) then
               j = j + 1
               idx(j) = i
            end if
         end do
         dl = 0.0_wp
         q = matmul(kb, v - vp0)
         do it = 1, 60
            ! residual: Kb^-1 q - (v - vp0) + sum dl_i a_i = 0; f_i = 0 (active)
            r(1:3) = matmul(kinv, q) - (v - vp0)
            jac = 0.0_wp
            jac(1:3, 1:3) = kinv
            do j = 1, na
               i = idx(j)
               r(1:3) = r(1:3) + dl(i)*grad(q, i)
               jac(1:3, 1:3) = jac(1:3, 1:3) + dl(i)*hess(i)
               jac(1:3, 3 + j) = grad(q, i)
               jac(3 + j, 1:3) = grad(q, i)
               fv = yield(q)
               r(3 + j) = fv(i)
            end do
            if (maxval(abs(r(1:3))) <= 1.0e-13_wp*max(maxval(abs(v - vp0)), &
                maxval(abs(matmul(kinv, q))), tiny(1.0_wp)) .and. &
                maxval(abs(r(4:3 + na))) <= TOL) exit
            dx(1:3 + na) = -r(1:3 + na)
            call solve_small(jac(1:3 + na, 1:3 + na), dx(1:3 + na), error)
            if (allocated(error)) return
            q = q + dx(1:3)
            do j = 1, na
               dl(idx(j)) = dl(idx(j)) + dx(3 + j)
            end do
         end do
         ! a negative multiplier leaves the set; a violated inactive end joins it
         changed = .false.
         do i = 1, 2
            if (active(i) .and. dl(i) < 0.0_wp) then
               active(i) = .false.
               changed = .true.
            end if
         end do
         fv = yield(q)
         if (im == 0.0_wp) fv(2) = 0.0_wp
         do i = 1, 2
            if (.not. active(i) .and. fv(i) > TOL) then
               active(i) = .true.
               changed = .true.
            end if
         end do
         if (.not. changed) exit
         if (.not. any(active)) then
            q = matmul(kb, v - vp0)
            dl = 0.0_wp
            return
         end if
      end do
      if (maxval(abs(yield(q)), mask=active) > 1.0e-8_wp) then
         call fatal_error(error, 'plate hinge return did not converge')
         return
      end if
      vp = vp0
      do i = 1, 2
         if (active(i)) vp = vp + dl(i)*grad(q, i)
      end do
      ! consistent tangent: the bordered system with unit right-hand sides dv
      jac = 0.0_wp
      jac(1:3, 1:3) = kinv
      j = 0
      do i = 1, 2
         if (.not. active(i)) cycle
         j = j + 1
         jac(1:3, 1:3) = jac(1:3, 1:3) + dl(i)*hess(i)
         jac(1:3, 3 + j) = grad(q, i)
         jac(3 + j, 1:3) = grad(q, i)
      end do
      na = j
      rhs = 0.0_wp
      do i = 1, 3
         rhs(i, i) = 1.0_wp
         dx(1:3 + na) = rhs(1:3 + na, i)
         call solve_small(jac(1:3 + na, 1:3 + na), dx(1:3 + na), error)
         if (allocated(error)) return
         kalg(:, i) = dx(1:3)
      end do
   contains
      pure function yield(qq) result(f)
         real(wp), intent(in) :: qq(3)
         real(wp) :: f(2)
         f(1) = ia*qq(1)**2 + im*qq(2)**2 - 1.0_wp
         f(2) = ia*qq(1)**2 + im*qq(3)**2 - 1.0_wp
      end function yield
      pure function grad(qq, i) result(a)
         real(wp), intent(in) :: qq(3)
         integer, intent(in) :: i
         real(wp) :: a(3)
         a = [2.0_wp*ia*qq(1), 0.0_wp, 0.0_wp]
         a(1 + i) = 2.0_wp*im*qq(1 + i)
      end function grad
      pure function hess(i) result(hm)
         integer, intent(in) :: i
         real(wp) :: hm(3, 3)
         hm = 0.0_wp
         hm(1, 1) = 2.0_wp*ia
         hm(1 + i, 1 + i) = 2.0_wp*im
      end function hess
   end subroutine hinge_update

   !> Solves a x = b in place (b becomes x) by Gaussian elimination with partial pivoting.
   subroutine solve_small(a, b, error)
      real(wp), intent(in) :: a(:, :)
      real(wp), intent(inout) :: b(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: m(size(a, 1), size(a, 2)), tmp(size(a, 2)), t, f
      integer :: n, k, i, p
      n = size(b)
      m = a
      do k = 1, n
         p = k - 1 + maxloc(abs(m(k:n, k)), 1)
         if (.not. abs(m(p, k)) > 0.0_wp) then
            call fatal_error(error, 'plate hinge: singular return system')
            return
         end if
         if (p /= k) then
            tmp = m(k, :)
            m(k, :) = m(p, :)
            m(p, :) = tmp
            t = b(k)
            b(k) = b(p)
            b(p) = t
         end if
         do i = k + 1, n
            f = m(i, k)/m(k, k)
            m(i, k:n) = m(i, k:n) - f*m(k, k:n)
            b(i) = b(i) - f*b(k)
         end do
      end do
      do k = n, 1, -1
         b(k) = (b(k) - dot_product(m(k, k + 1:n), b(k + 1:n)))/m(k, k)
      end do
   end subroutine solve_small

end module pecplas_structures_hinge
