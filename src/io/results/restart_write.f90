!> The restart state of an increment as /restart_next of a results file (then swapped to
!> /restart, pecplas_io_results_restart): each item as its values, or, for an item given
!> by reference to a field of the increment, a hard link to that field's dataset.
module pecplas_io_results_restart_write
   use hdf5, only: hid_t
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_base_strings, only: itoa
   use pecplas_io_results_increment, only: increment_result_t
   use pecplas_io_results_h5, only: h5_close_group, h5_exists, increment_group
   use pecplas_io_results_restart, only: restart_data_t, restart_item_t, restart_next_open, &
      restart_put, restart_link
   use pecplas_io_results_xdmf, only: xdmf_layout_t
   implicit none (type, external)
   private

   public :: write_restart

contains

   !> The restart state as /restart_next of `file`: its values, and for an item given by
   !> reference to a field of `inc`, a hard link to that field's dataset when written in
   !> this increment, else the field's values (written unscaled, as the fields are).
   subroutine write_restart(file, inc, restart, layout, error)
      type(xdmf_layout_t), intent(in) :: layout
      integer(hid_t), intent(in) :: file
      type(increment_result_t), intent(in) :: inc
      type(restart_data_t), intent(in) :: restart
      type(error_t), allocatable, intent(out) :: error
      integer(hid_t) :: g
      integer :: i
      call restart_next_open(file, g, error)
      if (allocated(error)) return
      do i = 1, restart%n
         associate (item => restart%items(i))
            if (allocated(item%v)) then
               call restart_put(g, item%name, size(item%v), item%v, error)
            else
               call put_field(file, g, inc, item, layout, error)
            end if
         end associate
         if (allocated(error)) exit
      end do
      call h5_close_group(g)
   end subroutine write_restart

   !> A restart item given by reference to a field of `inc` (see restart_item_t).
   subroutine put_field(file, g, inc, item, layout, error)
      type(xdmf_layout_t), intent(in) :: layout
      integer(hid_t), intent(in) :: file, g
      type(increment_result_t), intent(in) :: inc
      type(restart_item_t), intent(in) :: item
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: path
      logical :: have
      have = inc%write_fields
      if (have .and. item%field /= 'displacement') have = item%set >= 1 .and. &
         item%set <= size(layout%sets) .and. allocated(inc%set_fields)
      if (.not. have) then
         call fatal_error(error, 'restart item '//item%name//' refers to the field '// &
            item%field//' of increment '//itoa(inc%global_increment)//', which has none')
         return
      end if
      path = increment_group(inc%global_increment)//'/'//item%field
      if (item%field /= 'displacement') path = increment_group(inc%global_increment)// &
         '/sets/'//layout%sets(item%set)%name//'/'//item%field
      if (h5_exists(file, path)) then
         call restart_link(file, g, item%name, path, error)
         return
      end if
      ! a field not written (e.g. *OUTPUT without stresses): its values
      if (item%field == 'displacement') then
         call restart_put(g, item%name, size(inc%displacement), inc%displacement, error)
         return
      end if
      associate (f => inc%set_fields(item%set))
         select case (item%field)
         case ('stress')
            if (allocated(f%stress)) &
               call restart_put(g, item%name, size(f%stress), f%stress, error)
            have = allocated(f%stress)
         case ('strain')
            if (allocated(f%strain)) &
               call restart_put(g, item%name, size(f%strain), f%strain, error)
            have = allocated(f%strain)
         case ('state')
            if (allocated(f%state)) &
               call restart_put(g, item%name, size(f%state), f%state, error)
            have = allocated(f%state)
         case default
            have = .false.
         end select
      end associate
      if (.not. have .and. .not. allocated(error)) call fatal_error(error, 'restart item '// &
         item%name//' refers to the field '//item%field//' of set '//itoa(item%set)// &
         ', which increment '//itoa(inc%global_increment)//' does not hold')
   end subroutine put_field

end module pecplas_io_results_restart_write
