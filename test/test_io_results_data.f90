!> Sample data for the results-file tests: a hand-built model (2 Q4 in set SOIL, 1 T3 in
!> set LINING), Gauss coordinates and increments with known arrays; bitwise comparison
!> and file helpers. Values use thirds and sevenths so that every mantissa bit matters.
module test_io_results_data
   use, intrinsic :: iso_fortran_env, only: int64, int8
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t, fatal_error
   use pecplas_model_type, only: model_t
   use pecplas_model_mesh, only: element_set_t, node_set_t, edge_set_t
   use pecplas_model_loads, only: load_pattern_t, LOAD_GRAVITY, LOAD_FORCE
   use pecplas_io_results_increment, only: increment_result_t, gauss_coordinates_t
   implicit none (type, external)
   private

   public :: sample_model, sample_gauss, sample_increment, same_bits, make_out_dir, copy_file
   public :: OUT_DIR

   !> Where the tests leave their files (read again by test/python/test_results_file.py).
   character(len=*), parameter :: OUT_DIR = 'output/test'

   interface same_bits
      module procedure same_bits_1, same_bits_2, same_bits_3
   end interface same_bits

contains

   !>  4---5---6      7 above 4-5 closes the T3 (4, 5, 7)
   !>  | 1 | 2 |
   !>  1---2---3
   function sample_model() result(model)
      type(model_t) :: model
      model%title = 'results file test'
      model%units = 'kN, m, kPa'
      model%deck_file = 'sample.inp'
      model%deck_text = '*TITLE'//new_line('a')//'r'//char(195)//char(169)//'sultats'// &
         new_line('a')//'*NODE'//new_line('a')
      allocate (model%mesh%x(2, 7), model%mesh%node_id(7))
      model%mesh%x(:, :) = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, &
         0.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 1.0_wp, 0.5_wp, 2.0_wp/3.0_wp + 1.0_wp], [2, 7])
      model%mesh%node_id(:) = [101, 102, 103, 104, 105, 106, 107]
      allocate (model%mesh%esets(2))
      model%mesh%esets(1) = element_set_t(name='SOIL', etype='Q4', &
         conn=reshape([1, 2, 5, 4, 2, 3, 6, 5], [4, 2]), ids=[11, 12], material='clay')
      model%mesh%esets(2) = element_set_t(name='LINING', etype='T3', &
         conn=reshape([4, 5, 7], [3, 1]), ids=[21], material='concrete')
      allocate (model%mesh%nsets(1), model%mesh%edge_sets(1))
      model%mesh%nsets(1) = node_set_t(name='BASE', nodes=[1, 2, 3])
      model%mesh%edge_sets(1) = edge_set_t(name='TOP', nodes=reshape([6, 5, 5, 4], [2, 2]))
      allocate (model%patterns(2))
      model%patterns(1)%name = 'WEIGHT'
      model%patterns(1)%kind = LOAD_GRAVITY
      model%patterns(2)%name = 'HEAD_LOAD'
      model%patterns(2)%kind = LOAD_FORCE
   end function sample_model

   !> Gauss coordinates: 4 points per Q4 (element centre +- 1/sqrt(12)), 1 per T3.
   function sample_gauss() result(g)
      type(gauss_coordinates_t), allocatable :: g(:)
      real(wp), parameter :: a = 0.5_wp/sqrt(3.0_wp)
      real(wp), parameter :: off(2, 4) = reshape([-a, -a, a, -a, a, a, -a, a], [2, 4])
      integer :: e, p
      allocate (g(2))
      allocate (g(1)%xy(2, 4, 2), g(2)%xy(2, 1, 1))
      do e = 1, 2
         do p = 1, 4
            g(1)%xy(:, p, e) = [e - 0.5_wp, 0.5_wp] + off(:, p)
         end do
      end do
      g(2)%xy(:, 1, 1) = [0.5_wp, (2.0_wp + 2.0_wp/3.0_wp + 1.0_wp)/3.0_wp]
   end function sample_gauss

   !> Global increment k of a 2-step run: step 1 has increments 1, 2; step 2 has 3.
   function sample_increment(k) result(inc)
      integer, intent(in) :: k
      type(increment_result_t) :: inc
      integer :: i, n, p, e, s
      integer, parameter :: NG(2) = [4, 1], NE(2) = [2, 1]
      inc%global_increment = k
      inc%step = merge(1, 2, k <= 2)
      inc%increment = merge(k, k - 2, k <= 2)
      inc%time = 0.5_wp*k
      allocate (inc%pattern_factors(2))
      inc%pattern_factors(:) = [min(1.0_wp, 0.5_wp*k), max(0.0_wp, (k - 2)/3.0_wp)]
      inc%iterations = k + 2
      inc%residual = 1.0e-5_wp/(3*k)
      inc%cpu_time = 0.1_wp*k/7.0_wp
      allocate (inc%displacement(2, 7), inc%reaction(2, 7), inc%set_fields(2))
      do n = 1, 7
         do i = 1, 2
            inc%displacement(i, n) = -k*1.0e-3_wp*(i + 2*n)/3.0_wp
            inc%reaction(i, n) = k*(10*i - n)/7.0_wp
         end do
      end do
      do s = 1, 2
         allocate (inc%set_fields(s)%stress(4, NG(s), NE(s)), inc%set_fields(s)%strain(4, NG(s), NE(s)))
         do e = 1, NE(s)
            do p = 1, NG(s)
               do i = 1, 4
                  inc%set_fields(s)%stress(i, p, e) = -k*100.0_wp*(i + 4*p + 16*e + 64*s)/7.0_wp
                  inc%set_fields(s)%strain(i, p, e) = inc%set_fields(s)%stress(i, p, e)/3.0e4_wp
               end do
            end do
         end do
      end do
   end function sample_increment

   logical function same_bits_1(a, b) result(same)
      real(wp), intent(in) :: a(:), b(:)
      same = size(a) == size(b)
      if (same) same = all(transfer(a, 1_int64, size(a)) == transfer(b, 1_int64, size(b)))
   end function same_bits_1

   logical function same_bits_2(a, b) result(same)
      real(wp), intent(in) :: a(:, :), b(:, :)
      same = all(shape(a) == shape(b))
      if (same) same = same_bits_1(reshape(a, [size(a)]), reshape(b, [size(b)]))
   end function same_bits_2

   logical function same_bits_3(a, b) result(same)
      real(wp), intent(in) :: a(:, :, :), b(:, :, :)
      same = all(shape(a) == shape(b))
      if (same) same = same_bits_1(reshape(a, [size(a)]), reshape(b, [size(b)]))
   end function same_bits_3

   !> mkdir -p OUT_DIR/crash (test code only: Fortran has no portable mkdir).
   subroutine make_out_dir(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: stat, cstat
      call execute_command_line('mkdir -p '//OUT_DIR//'/crash', exitstat=stat, cmdstat=cstat)
      if (stat /= 0 .or. cstat /= 0) call fatal_error(error, 'cannot create '//OUT_DIR)
   end subroutine make_out_dir

   !> Byte copy of a file (the on-disk state a crash would leave, when src is still open).
   subroutine copy_file(src, dst, error)
      character(len=*), intent(in) :: src, dst
      type(error_t), allocatable, intent(out) :: error
      integer(int8), allocatable :: bytes(:)
      integer :: u, ios, nbytes
      open (newunit=u, file=src, access='stream', form='unformatted', action='read', &
         status='old', iostat=ios)
      if (ios == 0) inquire (unit=u, size=nbytes)
      if (ios == 0) then
         allocate (bytes(nbytes))
         read (u, iostat=ios) bytes
         close (u)
      end if
      if (ios /= 0) then
         call fatal_error(error, 'cannot read '//src)
         return
      end if
      open (newunit=u, file=dst, access='stream', form='unformatted', action='write', &
         status='replace', iostat=ios)
      if (ios == 0) write (u, iostat=ios) bytes
      if (ios == 0) close (u, iostat=ios)
      if (ios /= 0) call fatal_error(error, 'cannot write '//dst)
   end subroutine copy_file

end module test_io_results_data
