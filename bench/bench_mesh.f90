!> Structured square meshes for the benchmarks, written as Gmsh 4.1 files (physical groups
!> base, top, sides, soil) with a deck that loads the top by a pressure.
module bench_mesh
   use pecplas_base_kinds, only: wp
   use pecplas_base_files, only: make_directories
   use pecplas_base_strings, only: itoa
   implicit none (type, external)
   private
   public :: write_square_msh, write_square_deck, write_square_keywords, square_case

contains

   !> n x n elements of type Q4 or Q8 on the unit square (10 m side).
   subroutine write_square_msh(path, etype, n)
      character(len=*), intent(in) :: path, etype
      integer, intent(in) :: n
      integer :: u, i, j, m, nnode, tag, k
      real(wp) :: h
      logical :: quad
      quad = etype == 'Q8'
      m = merge(2*n, n, quad)        ! grid intervals per side
      h = 10.0_wp/m
      nnode = (m + 1)**2
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '$MeshFormat', '4.1 0 8', '$EndMeshFormat'
      write (u, '(a)') '$PhysicalNames', '4', '1 1 "base"', '1 2 "top"', '1 3 "sides"', &
         '2 4 "soil"', '$EndPhysicalNames'
      write (u, '(a)') '$Entities', '0 3 1 0'
      write (u, '(a)') '1 0 0 0 10 0 0 1 1 0', '2 0 10 0 10 10 0 1 2 0', '3 0 0 0 10 10 0 1 3 0'
      write (u, '(a)') '1 0 0 0 10 10 0 1 4 3 1 2 3', '$EndEntities'
      ! all nodes in one block (centre nodes of the quadratic grid are simply unused)
      write (u, '(a)') '$Nodes'
      write (u, '(i0,1x,i0,1x,i0,1x,i0)') 1, nnode, 1, nnode
      write (u, '(i0,1x,i0,1x,i0,1x,i0)') 2, 1, 0, nnode
      write (u, '(i0)') (k, k=1, nnode)
      do j = 0, m
         do i = 0, m
            write (u, '(es23.16,1x,es23.16,a)') i*h, j*h, ' 0'
         end do
      end do
      write (u, '(a)') '$EndNodes', '$Elements'
      write (u, '(i0,1x,i0,1x,i0,1x,i0)') 4, 4*n + n*n, 1, 4*n + n*n
      tag = 0
      call line_block(1, [(node(i, 0), i=0, m)])
      call line_block(2, [(node(i, m), i=0, m)])
      ! sides: left (upwards) then right
      write (u, '(a,i0)') '1 3 '//merge('8 ', '1 ', quad), 2*n
      call line_nodes([(node(0, j), j=0, m)])
      call line_nodes([(node(m, j), j=0, m)])
      write (u, '(a,i0)') '2 1 '//merge('16 ', '3  ', quad), n*n
      do j = 0, m - 1, merge(2, 1, quad)
         do i = 0, m - 1, merge(2, 1, quad)
            tag = tag + 1
            if (quad) then
               write (u, '(*(i0,:,1x))') tag, node(i, j), node(i + 2, j), node(i + 2, j + 2), &
                  node(i, j + 2), node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 2), &
                  node(i, j + 1)
            else
               write (u, '(*(i0,:,1x))') tag, node(i, j), node(i + 1, j), node(i + 1, j + 1), &
                  node(i, j + 1)
            end if
         end do
      end do
      write (u, '(a)') '$EndElements'
      close (u)
   contains
      integer function node(ii, jj)
         integer, intent(in) :: ii, jj
         node = 1 + ii + jj*(m + 1)
      end function node
      subroutine line_block(curve, nodes)
         integer, intent(in) :: curve, nodes(:)
         write (u, '(a,i0,a,i0)') '1 ', curve, ' '//merge('8 ', '1 ', quad), n
         call line_nodes(nodes)
      end subroutine line_block
      subroutine line_nodes(nodes)
         integer, intent(in) :: nodes(:)
         integer :: e
         do e = 1, n
            tag = tag + 1
            if (quad) then
               write (u, '(*(i0,:,1x))') tag, nodes(2*e - 1), nodes(2*e + 1), nodes(2*e)
            else
               write (u, '(*(i0,:,1x))') tag, nodes(e), nodes(e + 1)
            end if
         end do
      end subroutine line_nodes
   end subroutine write_square_msh

   !> The command line `ETYPE N [DIR] ...` of the square benchmarks (DIR: build/bench by
   !> default): writes the N x N square of ETYPE elements there (Gmsh file and deck) and
   !> returns the path of both without extension.
   subroutine square_case(usage, etype, n, base)
      character(len=*), intent(in) :: usage
      character(len=:), allocatable, intent(out) :: etype, base
      integer, intent(out) :: n
      character(len=64) :: arg
      character(len=:), allocatable :: dir
      if (command_argument_count() < 2) error stop usage
      call get_command_argument(1, arg); etype = trim(arg)
      call get_command_argument(2, arg); read (arg, *) n
      dir = 'build/bench'
      if (command_argument_count() >= 3) then
         call get_command_argument(3, arg); dir = trim(arg)
      end if
      call make_directories(dir)
      write (arg, '(a,a,i0)') etype, '_', n
      base = dir//'/square_'//trim(arg)
      call write_square_msh(base//'.msh', etype, n)
      call write_square_deck(base//'.inp', 'square_'//trim(arg)//'.msh')
   end subroutine square_case

   subroutine write_square_deck(path, msh)
      character(len=*), intent(in) :: path, msh
      integer :: u
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'benchmark: elastic square under a top pressure', &
         '*MESH, FILE='//msh, '*MATERIAL, NAME=soil', 'E = 1e5, NU = 0.3', &
         '*SECTION, SET=soil, MATERIAL=soil', '*BOUNDARY', 'base, XY', 'sides, X', &
         '*LOAD, NAME=p, TYPE=PRESSURE', 'top, 100', '*STEP, NAME=load, INCREMENTS=1', 'p, 1'
      close (u)
   end subroutine write_square_deck

   !> The Q4 mesh of write_square_msh(path, 'Q4', n) as a keyword deck (*NODES, *ELEMENTS,
   !> *NSET, *EDGES: the same node ids, coordinates, sets and load as write_square_deck).
   subroutine write_square_keywords(path, n)
      character(len=*), intent(in) :: path
      integer, intent(in) :: n
      integer :: u, i, j, k
      real(wp) :: h
      h = 10.0_wp/n
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'benchmark: elastic square under a top pressure (keywords)', &
         '*NODES'
      k = 0
      do j = 0, n
         do i = 0, n
            k = k + 1
            write (u, '(i0,a,es23.16,a,es23.16)') k, ', ', i*h, ', ', j*h
         end do
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=soil'
      k = 0
      do j = 0, n - 1
         do i = 0, n - 1
            k = k + 1
            write (u, '(*(i0,:,", "))') k, node(i, j), node(i + 1, j), node(i + 1, j + 1), &
               node(i, j + 1)
         end do
      end do
      write (u, '(a)') '*NSET, NAME=base, GENERATE', '1, '//itoa(n + 1)//', 1'
      write (u, '(a)') '*NSET, NAME=sides'
      write (u, '(*(i0,:,", "))') (node(0, j), node(n, j), j=0, n)
      write (u, '(a)') '*EDGES, NAME=top'
      do i = 0, n - 1
         write (u, '(i0,", ",i0)') node(i, n), node(i + 1, n)
      end do
      write (u, '(a)') '*MATERIAL, NAME=soil', 'E = 1e5, NU = 0.3', &
         '*SECTION, SET=soil, MATERIAL=soil', '*BOUNDARY', 'base, XY', 'sides, X', &
         '*LOAD, NAME=p, TYPE=PRESSURE', 'top, 100', '*STEP, NAME=load, INCREMENTS=1', 'p, 1'
      close (u)
   contains
      integer function node(ii, jj)
         integer, intent(in) :: ii, jj
         node = 1 + ii + jj*(n + 1)
      end function node
   end subroutine write_square_keywords

end module bench_mesh
