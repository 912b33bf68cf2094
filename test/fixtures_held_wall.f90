!> The held wall of the water and joint suites: a column of Q4 soil (width `width`, `ne`
!> elements of height `length`) beside a clamped plate wall, joined by GOODMAN4 joints of a
!> smooth elastic law, sand E = 3e4 kPa, nu = 0.3, gamma_unsat = 18, a geostatic K0 state
!> and one nil step (test_joint_k0_lobatto, test_water_joint_level).
module fixtures_held_wall
   use pecplas_base_kinds, only: wp
   implicit none (type, external)
   private
   public :: write_held_wall

contains

   !> Writes the deck to `deck`: `integration` the joints' INTEGRATION ('' for the default),
   !> `level` the phreatic level (none when absent; the plate then takes no water: NONE).
   subroutine write_held_wall(deck, ne, length, width, gamma_sat, k0, integration, level)
      character(len=*), intent(in) :: deck, integration
      integer, intent(in) :: ne
      real(wp), intent(in) :: length, width, gamma_sat, k0
      real(wp), intent(in), optional :: level
      character(len=64) :: buf
      integer :: u, r
      open (newunit=u, file=deck, status='replace', action='write')
      write (u, '(a)') '*TITLE', 'held wall with joints', '*UNITS', 'kN, m, kPa', '*NODES'
      do r = 0, ne
         ! soil nodes 2 r + 1 (x = 0) and 2 r + 2 (x = width); wall nodes 100 + r
         write (u, '(i0,a,g0)') 2*r + 1, ', 0, ', length*r
         write (u, '(i0,a,g0,a,g0)') 2*r + 2, ', ', width, ', ', length*r
         write (u, '(i0,a,g0)') 100 + r, ', 0, ', length*r
      end do
      write (u, '(a)') '*ELEMENTS, TYPE=Q4, SET=soil'
      do r = 0, ne - 1
         write (u, '(i0,4(a,i0))') r + 1, ', ', 2*r + 1, ', ', 2*r + 2, ', ', 2*r + 4, ', ', &
            2*r + 3
      end do
      write (buf, '(a,g0)') 'GAMMA_SAT = ', gamma_sat
      write (u, '(a)') '*MATERIAL, NAME=sand', 'E = 3e4, NU = 0.3, GAMMA_UNSAT = 18, '// &
         trim(buf), '*SECTION, SET=soil, MATERIAL=sand', '*NSET, NAME=wall, GENERATE'
      write (u, '(i0,a,i0,a)') 100, ', ', 100 + ne, ', 1'
      write (u, '(a)') '*NSET, NAME=base', '1, 2', '*NSET, NAME=right, GENERATE'
      write (u, '(i0,a,i0,a)') 4, ', ', 2*ne + 2, ', 2'
      write (u, '(a)') '*BOUNDARY', 'base, XY', 'right, X', 'wall, ALL', &
         '*PLATE, SET=wall, NODES=wall, EA=1e7, EI=1e5', &
         '*INTERFACE_LAW, NAME=smooth, TYPE=ELASTIC', 'KN = 1e6, KT = 1e-6'
      if (len(integration) > 0) then
         write (u, '(a)') '*JOINTS, TYPE=GOODMAN4, SET=wif, LAW=smooth, INTEGRATION='// &
            integration
      else
         write (u, '(a)') '*JOINTS, TYPE=GOODMAN4, SET=wif, LAW=smooth'
      end if
      do r = 0, ne - 1
         ! face 1: the wall walked downwards (normal +x, into the soil); face 2: the soil
         write (u, '(i0,4(a,i0))') 1000 + r, ', ', 101 + r, ', ', 100 + r, ', ', 2*r + 1, &
            ', ', 2*r + 3
      end do
      if (present(level)) then
         write (u, '(a,g0)') '*WATER, NAME=gwt, GAMMA_W=10, LEVEL=', level
         write (u, '(a)') '*PLATE_WATER', 'wall, NONE'
      end if
      write (u, '(a)') '*INITIAL_STRESS, TYPE=GEOSTATIC'
      write (u, '(a,g0)') 'ALL, 10, ', k0
      write (u, '(a)') '*STEP, NAME=nil, INCREMENTS=1', '*END STEP'
      close (u)
   end subroutine write_held_wall

end module fixtures_held_wall
