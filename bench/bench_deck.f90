!> Benchmark of the keyword-deck reader: `pecplas-bench-deck N [DIR] [--run]` writes an
!> N x N plane-strain Q4 square (pecplas-bench's mesh) twice, as a Gmsh file read by *MESH
!> and as the same mesh in keyword form (*NODES, *ELEMENTS, *NSET, *EDGES), reads both
!> decks, checks that they give the same mesh, and prints one line: equations, read time of
!> the keyword deck, read time of the *MESH deck, their ratio. With --run the keyword deck is
!> then run through the whole program (elastic, one increment) and the line adds the total
!> wall time and the share of the keyword read in it.
program bench_deck
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_type, only: model_t
   use pecplas_io_deck_reader, only: read_deck
   use pecplas_cmd_pecplas, only: run_deck
   use pecplas_problem_type, only: problem_t
   use pecplas_base_timers, only: wall_time
   use pecplas_base_files, only: make_directories
   use bench_mesh, only: write_square_msh, write_square_deck, write_square_keywords
   use pecplas_linalg_blas_core, only: blas_core_start
   implicit none (type, external)
   character(len=64) :: arg
   character(len=:), allocatable :: dir, base
   integer :: n, i, code
   logical :: run
   type(model_t) :: kw, msh
   type(problem_t) :: problem
   type(error_t), allocatable :: error
   real(wp) :: t0, t_kw, t_msh, total

   call blas_core_start() ! OpenBLAS's kernels: may run this program again (doc/build.md)
   if (command_argument_count() < 1) error stop 'usage: pecplas-bench-deck N [DIR] [--run]'
   call get_command_argument(1, arg); read (arg, *) n
   dir = 'build/bench'
   run = .false.
   do i = 2, command_argument_count()
      call get_command_argument(i, arg)
      if (trim(arg) == '--run') then
         run = .true.
      else
         dir = trim(arg)
      end if
   end do
   call make_directories(dir)
   write (arg, '(a,i0)') 'deck_Q4_', n
   base = dir//'/'//trim(arg)
   call write_square_msh(base//'.msh', 'Q4', n)
   call write_square_deck(base//'_mesh.inp', trim(arg)//'.msh')
   call write_square_keywords(base//'_kw.inp', n)

   t0 = wall_time()
   call read_deck(base//'_mesh.inp', msh, error)
   t_msh = wall_time() - t0
   if (allocated(error)) error stop 'bench: the *MESH deck failed'
   t0 = wall_time()
   call read_deck(base//'_kw.inp', kw, error)
   t_kw = wall_time() - t0
   if (allocated(error)) then
      print '(a)', error%message
      error stop 'bench: the keyword deck failed'
   end if
   ! the same mesh both ways (coordinates are written with 17 digits: read back exactly)
   if (kw%mesh%nnode() /= msh%mesh%nnode()) error stop 'bench: node counts differ'
   if (any(kw%mesh%x /= msh%mesh%x)) error stop 'bench: coordinates differ'
   if (any(kw%mesh%esets(1)%conn /= msh%mesh%esets(1)%conn)) error stop 'bench: elements differ'

   if (.not. run) then
      write (*, '(i9,3f10.3)') 2*kw%mesh%nnode(), t_kw, t_msh, t_kw/t_msh
      stop
   end if
   t0 = wall_time()
   code = run_deck(base//'_kw.inp', base//'_kw.h5', .true., kw, problem)
   total = wall_time() - t0
   if (code /= 0) error stop 'bench: the keyword deck run failed'
   write (*, '(i9,3f10.3,f10.3,f8.1)') 2*kw%mesh%nnode(), t_kw, t_msh, t_kw/t_msh, total, &
      100.0_wp*t_kw/total
end program bench_deck
