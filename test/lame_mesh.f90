!> Writes decks of the Lamé thick cylinder (inner radius A, outer radius B, internal
!> pressure P) for the verification tests: a quarter ring in plane strain, or an axial slice
!> r in [A, B], z in [0, H] in axisymmetry with u_z = 0 on both faces (the same solution).
module lame_mesh
   use pecplas_kinds, only: wp
   implicit none (type, external)
   private

   public :: write_lame_deck, lame_exact, A, B, P, E, NU

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

   !> Structured mesh of nr x nt cells in (r, theta) [plane] or (r, z) [axi] with element
   !> type etype (T3, T6, Q4, Q8); a quadratic grid (2nr+1) x (2nt+1) is used for T6/Q8.
   subroutine write_lame_deck(path, etype, axi, nr, nt)
      character(len=*), intent(in) :: path, etype
      logical, intent(in) :: axi
      integer, intent(in) :: nr, nt
      integer :: u, i, j, mr, mt, step, id, eid
      real(wp) :: r, t, x, y
      logical :: quad
      quad = etype == 'T6' .or. etype == 'Q8'
      step = merge(2, 1, quad)
      mr = step*nr; mt = step*nt
      open (newunit=u, file=path, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'Lame thick cylinder '//etype
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
            case ('Q8')
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
      write (u, '(a)') '*MATERIAL, NAME=steel, TYPE=ELASTIC'
      write (u, '(a,es24.16,a,es24.16)') 'E = ', E, ', NU = ', NU
      write (u, '(a)') '*SECTION, SET=ring, MATERIAL=steel'
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
      write (u, '(a)') '*LOAD, NAME=internal, TYPE=PRESSURE'
      write (u, '(a,es24.16)') 'inner, ', P
      write (u, '(a)') '*STEP, NAME=pressurise, INCREMENTS=1'
      write (u, '(a)') 'internal, 1.0'
      write (u, '(a)') '*SOLVER, TOLERANCE=1e-10'
      close (u)
   contains
      integer function node(ii, jj)
         integer, intent(in) :: ii, jj
         node = 1 + ii + jj*(mr + 1)
      end function node
   end subroutine write_lame_deck

end module lame_mesh
