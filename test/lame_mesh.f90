!> Writes decks of the Lamé thick cylinder (inner radius A, outer radius B, internal
!> pressure P) for the verification tests: a quarter ring in plane strain, or an axial slice
!> r in [A, B], z in [0, H] in axisymmetry with u_z = 0 on both faces (the same solution).
module lame_mesh
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private

   public :: write_lame_deck, lame_exact, A, B, P, E, NU
   public :: write_ring_mesh, ring_node, ring_quadratic

   real(wp), parameter :: A = 1.0_wp, B = 2.0_wp, P = 100.0_wp, E = 1.0e4_wp, NU = 0.3_wp
   real(wp), parameter :: PI = acos(-1.0_wp)

contains

   !> Exact radial displacement and hoop stress at radius r (plane strain).
   pure subroutine lame_exact(r, ur, hoop)
      real(wp), intent(in) :: r
      real(wp), intent(out) :: ur, hoop
      real(wp) :: c
      c = P*A**2/(B**2 - A**2)
      ur = c*(1.0_wp + NU)/E*((1.0_wp - 2.0_wp*NU)*r + B**2/r)
      hoop = c*(1.0_wp + B**2/r**2)
   end subroutine lame_exact

   !> Deck of the Lamé problem (elastic ring, internal pressure P, one increment) on the
   !> ring_mesh of nr x nt cells with element type etype.
   subroutine write_lame_deck(path, etype, axi, nr, nt)
      character(len=*), intent(in) :: path, etype
      logical, intent(in) :: axi
      integer, intent(in) :: nr, nt
      integer :: u
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'Lame thick cylinder '//etype
      call write_ring_mesh(u, etype, axi, nr, nt)
      write (u, '(a)') '*MATERIAL, NAME=steel, TYPE=ELASTIC'
      write (u, '(a,es24.16,a,es24.16)') 'E = ', E, ', NU = ', NU
      write (u, '(a)') '*SECTION, SET=ring, MATERIAL=steel'
      write (u, '(a)') '*LOAD, NAME=internal, TYPE=PRESSURE'
      write (u, '(a,es24.16)') 'inner, ', P
      write (u, '(a)') '*STEP, NAME=pressurise, INCREMENTS=1'
      write (u, '(a)') 'internal, 1.0'
      write (u, '(a)') '*SOLVER, TOLERANCE=1e-10'
      close (u)
   end subroutine write_lame_deck

   !> Writes to unit u the *ANALYSIS line and a structured mesh of nr x nt cells in
   !> (r, theta) [plane: quarter ring] or (r, z) [axi] with element type etype (T3, T6,
   !> Q4, Q8, Q8R); a quadratic grid (2nr+1) x (2nt+1) numbered by ring_node is used for
   !> T6/Q8/Q8R. Element set 'ring', node sets 'bottom' and 'top' on symmetry rollers
   !> (u_z = 0 on both faces in axi), edge set 'inner' (r = A).
   subroutine write_ring_mesh(u, etype, axi, nr, nt)
      integer, intent(in) :: u
      character(len=*), intent(in) :: etype
      logical, intent(in) :: axi
      integer, intent(in) :: nr, nt
      integer :: i, j, mr, mt, step, eid
      real(wp) :: r, t, x, y
      logical :: quad
      quad = ring_quadratic(etype)
      step = merge(2, 1, quad)
      mr = step*nr; mt = step*nt
      if (axi) then
         write (u, '(a)') '*ANALYSIS, TYPE=AXISYMMETRIC'
      else
         write (u, '(a)') '*ANALYSIS, TYPE=PLANE_STRAIN'
      end if
      write (u, '(a)') '*NODES'
      do j = 0, mt
         do i = 0, mr
            r = A + (B - A)*real(i, wp)/mr
            if (axi) then
               x = r; y = 0.5_wp*real(j, wp)/mt
            else
               t = 0.5_wp*PI*real(j, wp)/mt
               x = r*cos(t); y = r*sin(t)
            end if
            write (u, '(i0,2(",",es24.16))') node(i, j), x, y
         end do
      end do
      write (u, '(a)') '*ELEMENTS, TYPE='//etype//', SET=ring'
      eid = 0
      do j = 0, mt - step, step
         do i = 0, mr - step, step
            select case (etype)
            case ('Q4')
               eid = eid + 1
               write (u, '(*(i0,:,","))') eid, node(i, j), node(i + 1, j), node(i + 1, j + 1), &
                  node(i, j + 1)
            case ('Q8', 'Q8R')
               eid = eid + 1
               write (u, '(*(i0,:,","))') eid, node(i, j), node(i + 2, j), node(i + 2, j + 2), &
                  node(i, j + 2), node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 2), &
                  node(i, j + 1)
            case ('T3')
               eid = eid + 1
               write (u, '(*(i0,:,","))') eid, node(i, j), node(i + 1, j), node(i + 1, j + 1)
               eid = eid + 1
               write (u, '(*(i0,:,","))') eid, node(i, j), node(i + 1, j + 1), node(i, j + 1)
            case ('T6')
               eid = eid + 1
               write (u, '(*(i0,:,","))') eid, node(i, j), node(i + 2, j), node(i + 2, j + 2), &
                  node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 1)
               eid = eid + 1
               write (u, '(*(i0,:,","))') eid, node(i, j), node(i + 2, j + 2), node(i, j + 2), &
                  node(i + 1, j + 1), node(i + 1, j + 2), node(i, j + 1)
            end select
         end do
      end do
      write (u, '(a)') '*NSET, NAME=bottom'
      write (u, '(*(i0,:,","))') (node(i, 0), i=0, mr)
      write (u, '(a)') '*NSET, NAME=top'
      write (u, '(*(i0,:,","))') (node(i, mt), i=0, mr)
      write (u, '(a)') '*BOUNDARY'
      write (u, '(a)') 'bottom, 2'
      if (axi) then
         write (u, '(a)') 'top, 2'
      else
         write (u, '(a)') 'top, 1'
      end if
      write (u, '(a)') '*EDGES, NAME=inner'
      do j = 0, mt - step, step
         if (quad) then
            write (u, '(*(i0,:,","))') node(0, j), node(0, j + 2), node(0, j + 1)
         else
            write (u, '(*(i0,:,","))') node(0, j), node(0, j + 1)
         end if
      end do
   contains
      integer function node(ii, jj)
         integer, intent(in) :: ii, jj
         node = ring_node(ii, jj, mr)
      end function node
   end subroutine write_ring_mesh

   !> Whether write_ring_mesh uses the quadratic grid for etype.
   pure logical function ring_quadratic(etype)
      character(len=*), intent(in) :: etype
      ring_quadratic = etype == 'T6' .or. etype == 'Q8' .or. etype == 'Q8R'
   end function ring_quadratic

   !> Id of grid node (i, j), i = 0..mr radial, j angular, on a grid of mr + 1 columns.
   pure integer function ring_node(i, j, mr)
      integer, intent(in) :: i, j, mr
      ring_node = 1 + i + j*(mr + 1)
   end function ring_node

end module lame_mesh
