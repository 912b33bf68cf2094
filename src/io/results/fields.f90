!> One increment in the results file: checks (shapes, finite values), the /history row and
!> the /increments/<NNNNNN> field group. Layout documented in pecplas_io_results_file.
module pecplas_io_results_fields
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use hdf5, only: hid_t
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_io_results_increment, only: increment_result_t, set_fields_t
   use pecplas_io_results_h5, only: h5_group, h5_close_group, h5_write, h5_attr, h5_append, &
      increment_group, h5_describe
   use pecplas_io_results_describe, only: results_units_t, XY, XYZ, STRESS_COMPONENTS
   use pecplas_io_results_xdmf, only: xdmf_layout_t
   implicit none (type, external)
   private

   public :: check_increment, write_history_row, write_fields, stress_mean, has_plastic_state

contains

   !> Refuses an increment the file cannot hold faithfully: wrong shapes, missing arrays or
   !> any NaN/Inf (a NaN in a results file would silently poison post-processing).
   subroutine check_increment(inc, layout, ngauss, npattern, strains, error)
      type(increment_result_t), intent(in) :: inc
      type(xdmf_layout_t), intent(in) :: layout
      integer, intent(in) :: ngauss(:), npattern
      logical, intent(in) :: strains
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: where
      character(len=16) :: buf
      integer :: s, nfac
      write (buf, '(i0)') inc%global_increment
      where = 'results file, increment '//trim(buf)//': '
      if (inc%global_increment <= 0) then
         call fatal_error(error, where//'the global increment number must be positive')
         return
      end if
      nfac = 0
      if (allocated(inc%pattern_factors)) nfac = size(inc%pattern_factors)
      if (nfac /= npattern) then
         call fatal_error(error, where//'pattern_factors needs one entry per load pattern')
         return
      end if
      if (.not. (ieee_is_finite(inc%time) .and. ieee_is_finite(inc%residual) .and. &
                 ieee_is_finite(inc%cpu_time))) then
         call fatal_error(error, where//'non-finite time, residual or cpu_time')
         return
      end if
      if (nfac > 0) then
         if (.not. all(ieee_is_finite(inc%pattern_factors))) then
            call fatal_error(error, where//'non-finite pattern factor')
            return
         end if
      end if
      if (.not. inc%write_fields) return
      call check_array(inc%displacement, [2, layout%nnode], where//'displacement', error)
      if (allocated(error)) return
      if (layout%reactions) then
         call check_array(inc%reaction, [2, layout%nnode], where//'reaction', error)
         if (allocated(error)) return
      end if
      if (.not. (layout%stresses .or. strains)) return
      if (.not. allocated(inc%set_fields)) then
         call fatal_error(error, where//'set_fields missing')
         return
      else if (size(inc%set_fields) /= size(layout%sets)) then
         call fatal_error(error, where//'set_fields needs one entry per element set')
         return
      end if
      do s = 1, size(layout%sets)
         associate (f => inc%set_fields(s), name => layout%sets(s)%name)
            if (layout%stresses) then
               call check_array3(f%stress, [4, ngauss(s), layout%sets(s)%nel], &
                  where//'stress of set '//name, error)
               if (allocated(error)) return
               ! what is written must be checked too: stress_mean is a derived array. Each
               ! mean is at most (1 + ngauss*eps) times the largest |stress|, so it can
               ! only overflow within a factor 2 of the largest double: only then is it
               ! computed here (at 10^6 unknowns it is 16 MB, and it is made again to be
               ! written)
               if (maxval(abs(f%stress)) >= huge(1.0_wp)/2) then
                  if (.not. all(ieee_is_finite(stress_mean(f%stress)))) then
                     call fatal_error(error, where//'stress_mean of set '//name// &
                        ' has a non-finite value')
                     return
                  end if
               end if
            end if
            if (strains) then
               call check_array3(f%strain, [4, ngauss(s), layout%sets(s)%nel], &
                  where//'strain of set '//name, error)
               if (allocated(error)) return
            end if
            if (allocated(f%state)) then
               if (size(f%state) > 0) then
                  call check_array3(f%state, [size(f%state, 1), ngauss(s), &
                     layout%sets(s)%nel], where//'material state of set '//name, error)
                  if (allocated(error)) return
               end if
            end if
         end associate
      end do
   end subroutine check_increment

   subroutine check_array(a, expected, what, error)
      real(wp), allocatable, intent(in) :: a(:, :)
      integer, intent(in) :: expected(2)
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      if (.not. allocated(a)) then
         call fatal_error(error, what//' missing')
      else if (any(shape(a) /= expected)) then
         call fatal_error(error, what//' has the wrong shape')
      else if (.not. all(ieee_is_finite(a))) then
         call fatal_error(error, what//' has a non-finite value')
      end if
   end subroutine check_array

   subroutine check_array3(a, expected, what, error)
      real(wp), allocatable, intent(in) :: a(:, :, :)
      integer, intent(in) :: expected(3)
      character(len=*), intent(in) :: what
      type(error_t), allocatable, intent(out) :: error
      if (.not. allocated(a)) then
         call fatal_error(error, what//' missing')
      else if (any(shape(a) /= expected)) then
         call fatal_error(error, what//' has the wrong shape')
      else if (.not. all(ieee_is_finite(a))) then
         call fatal_error(error, what//' has a non-finite value')
      end if
   end subroutine check_array3

   !> Appends row `row` to every /history dataset.
   subroutine write_history_row(file, row, inc, error)
      integer(hid_t), intent(in) :: file
      integer, intent(in) :: row
      type(increment_result_t), intent(in) :: inc
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: none(0)
      integer :: fields
      fields = 0
      if (inc%write_fields) fields = 1
      call h5_append(file, 'history/step', row, inc%step, error)
      if (.not. allocated(error)) call h5_append(file, 'history/increment', row, inc%increment, &
         error)
      if (.not. allocated(error)) call h5_append(file, 'history/global_increment', row, &
         inc%global_increment, error)
      if (.not. allocated(error)) call h5_append(file, 'history/iterations', row, &
         inc%iterations, error)
      if (.not. allocated(error)) call h5_append(file, 'history/fields', row, fields, error)
      if (.not. allocated(error)) call h5_append(file, 'history/method', row, inc%method, error)
      if (.not. allocated(error)) call h5_append(file, 'history/line_searches', row, &
         inc%line_searches, error)
      if (.not. allocated(error)) call h5_append(file, 'history/control', row, inc%control, error)
      if (.not. allocated(error)) call h5_append(file, 'history/time', row, inc%time, error)
      if (.not. allocated(error)) call h5_append(file, 'history/residual', row, inc%residual, &
         error)
      if (.not. allocated(error)) call h5_append(file, 'history/cpu_time', row, inc%cpu_time, &
         error)
      if (allocated(error)) return
      if (allocated(inc%pattern_factors)) then
         call h5_append(file, 'history/pattern_factors', row, inc%pattern_factors, error)
      else
         call h5_append(file, 'history/pattern_factors', row, none, error)
      end if
   end subroutine write_history_row

   !> Writes the field group of `inc` (already checked by check_increment), each dataset
   !> with its `units` and `components`.
   subroutine write_fields(file, inc, layout, strains, units, error)
      integer(hid_t), intent(in) :: file
      type(increment_result_t), intent(in) :: inc
      type(xdmf_layout_t), intent(in) :: layout
      logical, intent(in) :: strains
      type(results_units_t), intent(in) :: units
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g, gsets, gs
      integer :: s
      gsets = -1
      call h5_group(file, increment_group(inc%global_increment), g, error)
      if (allocated(error)) return
      call h5_attr(g, 'step', inc%step, error)
      if (.not. allocated(error)) call h5_attr(g, 'increment', inc%increment, error)
      if (.not. allocated(error)) call h5_attr(g, 'global_increment', inc%global_increment, error)
      if (.not. allocated(error)) call h5_attr(g, 'time', inc%time, error)
      if (inc%estimated .and. .not. allocated(error)) then
         call h5_attr(g, 'error_estimate', inc%error_estimate, error)
         if (.not. allocated(error)) call h5_attr(g, 'energy_norm', inc%energy_norm, error)
      end if
      if (.not. allocated(error)) call h5_write(g, 'displacement', inc%displacement, error)
      if (.not. allocated(error)) call h5_write(g, 'displacement3', pad3(inc%displacement), error)
      if (.not. allocated(error)) call h5_describe(g, 'displacement', units%length, error, XY)
      if (.not. allocated(error)) call h5_describe(g, 'displacement3', units%length, error, XYZ)
      if (layout%reactions) then
         if (.not. allocated(error)) call h5_write(g, 'reaction', inc%reaction, error)
         if (.not. allocated(error)) call h5_write(g, 'reaction3', pad3(inc%reaction), error)
         if (.not. allocated(error)) call h5_describe(g, 'reaction', units%force, error, XY)
         if (.not. allocated(error)) call h5_describe(g, 'reaction3', units%force, error, XYZ)
      end if
      if (.not. allocated(error) .and. (layout%stresses .or. strains .or. inc%estimated)) &
         call h5_group(g, 'sets', gsets, error)
      if (.not. allocated(error) .and. gsets > 0) then
         do s = 1, size(layout%sets)
            ! a set not active in the phase under way (removed, not yet installed): no fields
            if (.not. layout%sets(s)%active) cycle
            call h5_group(gsets, layout%sets(s)%name, gs, error)
            if (allocated(error)) exit
            associate (f => inc%set_fields(s))
               if (layout%stresses) then
                  call h5_write(gs, 'stress', f%stress, error)
                  if (.not. allocated(error)) &
                     call h5_write(gs, 'stress_mean', stress_mean(f%stress), error)
                  if (.not. allocated(error)) call h5_describe(gs, 'stress', units%stress, &
                     error, STRESS_COMPONENTS)
                  if (.not. allocated(error)) call h5_describe(gs, 'stress_mean', &
                     units%stress, error, STRESS_COMPONENTS)
                  if (allocated(f%pore_steady) .and. .not. allocated(error)) &
                     call write_pore(gs, f, units%stress, error)
               end if
               if (strains .and. .not. allocated(error)) then
                  call h5_write(gs, 'strain', f%strain, error)
                  if (.not. allocated(error)) call h5_describe(gs, 'strain', '1', error, &
                     STRESS_COMPONENTS)
               end if
               if (allocated(f%state) .and. .not. allocated(error)) then
                  if (size(f%state) > 0) call write_state(gs, f%state, units%sets(s)%state, &
                     error)
                  if (.not. allocated(error) .and. has_plastic_state(units%sets(s)%state)) &
                     call write_plastic(gs, f%state, units%sets(s)%state, error)
               end if
               if (allocated(f%error_indicator) .and. .not. allocated(error)) &
                  call h5_write(gs, 'error_indicator', f%error_indicator, error)
            end associate
            call h5_close_group(gs)
            if (allocated(error)) exit
         end do
      end if
      call h5_close_group(gsets)
      call h5_close_group(g)
   end subroutine write_fields

   !> Groundwater: the steady and excess pore pressures (ngauss, nel, compression
   !> positive) and the total stress sigma' - (p_steady + p_excess) m (4, ngauss, nel).
   subroutine write_pore(gs, f, unit, error)
      integer(hid_t), intent(in) :: gs
      type(set_fields_t), intent(in) :: f
      character(len=*), intent(in) :: unit
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: total(:, :, :)
      integer :: k
      total = f%stress
      do k = 1, 3
         total(k, :, :) = total(k, :, :) - (f%pore_steady + f%pore_excess)
      end do
      call h5_write(gs, 'pore_steady', f%pore_steady, error)
      if (.not. allocated(error)) call h5_write(gs, 'pore_excess', f%pore_excess, error)
      if (.not. allocated(error)) call h5_write(gs, 'total_stress', total, error)
      if (.not. allocated(error)) call h5_describe(gs, 'pore_steady', unit, error)
      if (.not. allocated(error)) call h5_describe(gs, 'pore_excess', unit, error)
      if (.not. allocated(error)) call h5_describe(gs, 'total_stress', unit, error, &
         STRESS_COMPONENTS)
   end subroutine write_pore

   !> A soil history dataset: all its values are strains or a return kind ("1"); its
   !> components are the material's state names when they match its first axis.
   subroutine write_state(gs, state, names, error)
      integer(hid_t), intent(in) :: gs
      real(wp), intent(in), contiguous :: state(:, :, :)
      character(len=*), intent(in) :: names(:)
      type(error_t), allocatable, intent(out) :: error
      call h5_write(gs, 'state', state, error)
      if (allocated(error)) return
      if (size(names) == size(state, 1)) then
         call h5_describe(gs, 'state', '1', error, names)
      else
         call h5_describe(gs, 'state', '1', error)
      end if
   end subroutine write_state

   !> Whether a soil history names the equivalent plastic strain and the return kind
   !> (Mohr-Coulomb, Drucker-Prager): its sets get the plastic indicators.
   pure logical function has_plastic_state(names) result(yes)
      character(len=*), intent(in) :: names(:)
      yes = any(names == 'eps_p_eq') .and. any(names == 'return_kind')
   end function has_plastic_state

   !> The plastic indicators of each element, cell values for ParaView: eps_p_eq, the mean
   !> of its Gauss points' equivalent plastic strain, and plastic_fraction, the fraction of
   !> its Gauss points whose last return was plastic (return kind > 0: yielding at this
   !> increment).
   subroutine write_plastic(gs, state, names, error)
      integer(hid_t), intent(in) :: gs
      real(wp), intent(in), contiguous :: state(:, :, :)
      character(len=*), intent(in) :: names(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: eps(:), fraction(:)
      integer :: ie, ik, e
      ie = findloc(names == 'eps_p_eq', .true., dim=1)
      ik = findloc(names == 'return_kind', .true., dim=1)
      if (ie < 1 .or. ik < 1 .or. max(ie, ik) > size(state, 1)) return
      allocate (eps(size(state, 3)), fraction(size(state, 3)))
      do e = 1, size(state, 3)
         eps(e) = sum(state(ie, :, e))/real(max(size(state, 2), 1), wp)
         fraction(e) = real(count(state(ik, :, e) > 0.5_wp), wp)/real(max(size(state, 2), 1), wp)
      end do
      call h5_write(gs, 'eps_p_eq', eps, error)
      if (.not. allocated(error)) call h5_describe(gs, 'eps_p_eq', '1', error)
      if (.not. allocated(error)) call h5_write(gs, 'plastic_fraction', fraction, error)
      if (.not. allocated(error)) call h5_describe(gs, 'plastic_fraction', '1', error)
   end subroutine write_plastic

   !> Plain average over the Gauss points of each element, mean(4, nel): a cell value for
   !> ParaView, not a volume average.
   pure function stress_mean(stress) result(mean)
      real(wp), intent(in) :: stress(:, :, :)
      real(wp), allocatable :: mean(:, :)
      real(wp) :: n
      integer :: e, ip
      ! dividing first keeps the mean of finite stresses finite (the sum may overflow); a
      ! loop, not sum(stress/n, dim=2), which makes a temporary of the size of stress
      n = real(size(stress, 2), wp)
      allocate (mean(size(stress, 1), size(stress, 3)))
      do e = 1, size(stress, 3)
         mean(:, e) = 0.0_wp
         do ip = 1, size(stress, 2)
            mean(:, e) = mean(:, e) + stress(:, ip, e)/n
         end do
      end do
   end function stress_mean

   !> (2, n) -> (3, n) with a zero third row.
   pure function pad3(a) result(b)
      real(wp), intent(in) :: a(:, :)
      real(wp), allocatable :: b(:, :)
      allocate (b(3, size(a, 2)))
      b(1:2, :) = a
      b(3, :) = 0.0_wp
   end function pad3

end module pecplas_io_results_fields
