!> Import of Gmsh meshes (.msh version 4.1, ASCII) into a mesh_t.
!>
!> - Nodes: Gmsh node tags become user ids (`node_id`), internal numbers follow file order.
!>   PECPLAS is 2D: a node with |z| > 1e-12 * (model size) is an error.
!> - Physical surface groups -> element sets named after the group ('PHYS<tag>' if unnamed);
!>   types 2 -> T3, 9 -> T6, 3 -> Q4, 16 -> Q8. A group mixing types is split into one set
!>   per type named '<name>_T3', '<name>_Q4', ... (a set has one element type).
!> - Physical curve groups -> an edge set (2-node or 3-node lines, not mixed; Gmsh's line3
!>   order end, end, mid is ours) and a node set of the same name with all its nodes.
!> - Physical point groups -> node sets. Physical volumes are ignored.
!> - Elements on entities without a physical group are ignored, as Gmsh does, unless the
!>   file has no physical group at all: then all 2D elements go to 'ALL_T3', 'ALL_Q4', ...
!> Edge sets keep Gmsh's direction and elements their node order: call check_elements and
!> orient_edge_sets (pecplas_model_mesh_tools) once the whole mesh is assembled.
module pecplas_io_mesh_gmsh
   use iso_fortran_env, only: int64
   use pecplas_base_kinds, only: wp
   use pecplas_base_error, only: error_t
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_node_lookup, only: node_lookup_t
   use pecplas_io_text_scanner, only: scanner_t
   use pecplas_io_mesh_gmsh_sets, only: gmsh_data_t, build_sets, grow, itoa, nodes_per_element
   implicit none (type, external)
   private

   public :: read_gmsh

contains

   !> Reads the Gmsh 4.1 ASCII file `path` into `mesh`. Errors name the file, line and section.
   subroutine read_gmsh(path, mesh, error)
      character(len=*), intent(in) :: path
      type(mesh_t), intent(out) :: mesh
      type(error_t), allocatable, intent(out) :: error
      type(scanner_t) :: sc
      type(gmsh_data_t) :: g
      character(len=:), allocatable :: section, previous
      logical :: got_format, got_nodes

      call sc%open(path, error)
      if (allocated(error)) return
      g%path = path
      got_format = .false.; got_nodes = .false.
      previous = '$MeshFormat'
      do while (sc%next())
         section = sc%token()
         if (.not. got_format .and. section /= '$MeshFormat') then
            call sc%fail(error, '$MeshFormat', &
               'not a Gmsh file: $MeshFormat expected first, got '''//section//'''')
            return
         end if
         select case (section)
         case ('$MeshFormat')
            call read_format(sc, error)
            got_format = .true.
         case ('$PhysicalNames')
            call read_names(sc, g, error)
         case ('$Entities')
            call read_entities(sc, g, error)
         case ('$Nodes')
            call read_nodes(sc, mesh, g, error)
            got_nodes = .true.
         case ('$Elements')
            if (.not. got_nodes) then
               call sc%fail(error, section, '$Elements before $Nodes')
               return
            end if
            call read_elements(sc, g, error)
         case default
            if (section(1:1) /= '$') then
               ! named by the section it follows (the counts of that one are likely off)
               call sc%fail(error, previous, 'expected a section name ($Name) after $End'// &
                  previous(2:)//', got '''//section//''' (counts do not match the data?)')
               return
            end if
            call skip_section(sc, section, error)
         end select
         if (allocated(error)) return
         previous = section
      end do
      if (.not. got_format) then
         call sc%fail(error, '$MeshFormat', 'empty file, not a Gmsh mesh')
         return
      end if
      if (.not. got_nodes) then
         call sc%fail(error, '$Nodes', 'no $Nodes section')
         return
      end if
      call build_sets(g, mesh, error)
   end subroutine read_gmsh

   !> "4.1 0 8": version 4.1, ASCII.
   subroutine read_format(sc, error)
      type(scanner_t), intent(inout) :: sc
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: version
      integer :: ftype, dsize
      call sc%get_word(version, '$MeshFormat', error)
      if (allocated(error)) return
      if (version /= '4.1') then
         call sc%fail(error, '$MeshFormat', 'Gmsh format version '//version//' is not supported;'// &
            ' save the mesh as version 4.1 ASCII (gmsh -format msh41, Mesh.MshFileVersion = 4.1)')
         return
      end if
      call sc%get_int(ftype, '$MeshFormat', error)
      if (allocated(error)) return
      if (ftype /= 0) then
         call sc%fail(error, '$MeshFormat', 'binary .msh files are not supported;'// &
            ' save the mesh as ASCII (Mesh.Binary = 0)')
         return
      end if
      call sc%get_int(dsize, '$MeshFormat', error)
      if (allocated(error)) return
      call expect(sc, '$EndMeshFormat', error)
   end subroutine read_format

   !> "n" then n lines "dim tag "name"".
   subroutine read_names(sc, g, error)
      type(scanner_t), intent(inout) :: sc
      type(gmsh_data_t), intent(inout) :: g
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: kw = '$PhysicalNames'
      integer :: n, i
      call sc%get_int(n, kw, error)
      if (allocated(error)) return
      ! a name line takes at least 8 bytes ('d t "n"' + newline)
      if (n < 0 .or. n > sc%remaining()/8) then
         call sc%fail(error, kw, itoa(n)//' physical names announced, more than the rest of'// &
            ' the file can hold (truncated file or wrong count?)')
         return
      end if
      allocate (g%names(max(n, 0)))
      do i = 1, n
         call sc%get_int(g%names(i)%dim, kw, error)
         if (allocated(error)) return
         call sc%get_int(g%names(i)%tag, kw, error)
         if (allocated(error)) return
         call sc%get_name(g%names(i)%name, kw, error)
         if (allocated(error)) return
      end do
      call expect(sc, '$EndPhysicalNames', error)
   end subroutine read_names

   !> Points, curves and surfaces with their physical tags; volumes are read and dropped.
   subroutine read_entities(sc, g, error)
      type(scanner_t), intent(inout) :: sc
      type(gmsh_data_t), intent(inout) :: g
      type(error_t), allocatable, intent(out) :: error
      integer :: counts(0:3), d
      integer, allocatable :: tag(:), ptr(:), phys(:)
      do d = 0, 3
         call sc%get_int(counts(d), '$Entities', error)
         if (allocated(error)) return
      end do
      ! an entity line takes at least 8 bytes (tag, a bounding box, a count)
      if (any(counts < 0) .or. sum(int(counts, int64)) > sc%remaining()/8) then
         call sc%fail(error, '$Entities', 'entity counts '//itoa(counts(0))//' '// &
            itoa(counts(1))//' '//itoa(counts(2))//' '//itoa(counts(3))//' do not fit in'// &
            ' the rest of the file (truncated file or wrong count?)')
         return
      end if
      do d = 0, 2
         call read_entity_list(sc, d, counts(d), tag, ptr, phys, error)
         if (allocated(error)) return
         call g%ents(d)%lookup%build_ids(tag, 'Gmsh entity tag', error)
         if (allocated(error)) then
            error%file = sc%path; error%line = sc%tok_line; error%keyword = '$Entities'
            return
         end if
         call move_alloc(tag, g%ents(d)%tag)
         call move_alloc(ptr, g%ents(d)%ptr)
         call move_alloc(phys, g%ents(d)%phys)
         if (size(g%ents(d)%phys) > 0) g%has_phys = .true.
      end do
      ! volumes: parsed (to find the section end) and dropped
      call read_entity_list(sc, 3, counts(3), tag, ptr, phys, error)
      if (allocated(error)) return
      call expect(sc, '$EndEntities', error)
   end subroutine read_entities

   !> n entities of dimension d: "tag bbox(3 or 6 reals) nphys phys... [nbound bound...]".
   subroutine read_entity_list(sc, d, n, tag, ptr, phys, error)
      type(scanner_t), intent(inout) :: sc
      integer, intent(in) :: d, n
      integer, allocatable, intent(out) :: tag(:), ptr(:), phys(:)
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: kw = '$Entities'
      integer :: i, j, nph, nb, idum, np
      real(wp) :: rdum
      allocate (tag(n), ptr(n + 1), phys(0))
      ptr(1) = 1; np = 0
      do i = 1, n
         call sc%get_int(tag(i), kw, error)
         do j = 1, merge(3, 6, d == 0)
            if (.not. allocated(error)) call sc%get_real(rdum, kw, error)
         end do
         if (.not. allocated(error)) call sc%get_int(nph, kw, error)
         if (allocated(error)) return
         if (nph < 0 .or. nph > sc%remaining()/2) then
            call sc%fail(error, kw, 'bad physical tag count '//itoa(nph))
            return
         end if
         call grow(phys, np + nph)
         do j = 1, nph
            call sc%get_int(phys(np + j), kw, error)
            if (allocated(error)) return
            phys(np + j) = abs(phys(np + j))
         end do
         np = np + nph
         ptr(i + 1) = np + 1
         if (d == 2 .and. nph > 1) then
            call sc%fail(error, kw, 'surface '//itoa(tag(i))//' is in several physical surface'// &
               ' groups; an element can be in only one element set')
            return
         end if
         if (d > 0) then
            call sc%get_int(nb, kw, error)
            do j = 1, nb
               if (.not. allocated(error)) call sc%get_int(idum, kw, error)
            end do
            if (allocated(error)) return
         end if
      end do
      phys = phys(1:np)
   end subroutine read_entity_list

   !> Entity blocks "dim tag parametric n", then n node tags, then n coordinate lines
   !> (x y z, plus the dim parametric coordinates when parametric = 1).
   subroutine read_nodes(sc, mesh, g, error)
      type(scanner_t), intent(inout) :: sc
      type(mesh_t), intent(inout) :: mesh
      type(gmsh_data_t), intent(inout) :: g
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: kw = '$Nodes'
      integer :: h(4), nnode, b, edim, param, nb, k, i, j, line0, zline, ztag
      real(wp) :: z, zmax, lo(3), hi(3), dum
      line0 = sc%tok_line
      call get_ints(sc, kw, h, error)
      if (allocated(error)) return
      nnode = h(2)
      if (nnode < 0) then
         call sc%fail(error, kw, 'negative node count')
         return
      end if
      ! a node takes at least 8 bytes ("t" + newline + "x y z" + newline)
      if (nnode > sc%remaining()/8) then
         call sc%fail(error, kw, itoa(nnode)//' nodes announced, but the rest of the file ('// &
            itoa64(sc%remaining())//' bytes) holds at most '//itoa64(sc%remaining()/8)// &
            ' (truncated file or wrong count?)')
         return
      end if
      allocate (mesh%x(2, nnode), mesh%node_id(nnode))
      k = 0; zmax = 0.0_wp; zline = 0; ztag = 0
      lo = huge(1.0_wp); hi = -huge(1.0_wp)
      do b = 1, h(1)
         call get_ints(sc, kw, h, error)
         if (allocated(error)) return
         edim = h(1); param = h(3); nb = h(4)
         if (nb < 0 .or. k + nb > nnode .or. edim < 0 .or. edim > 3) then
            call sc%fail(error, kw, 'bad entity block header (more nodes than announced?)')
            return
         end if
         do i = k + 1, k + nb
            call sc%get_int(mesh%node_id(i), kw, error)
            if (allocated(error)) return
         end do
         do i = k + 1, k + nb
            call sc%get_real(mesh%x(1, i), kw, error)
            if (.not. allocated(error)) call sc%get_real(mesh%x(2, i), kw, error)
            if (.not. allocated(error)) call sc%get_real(z, kw, error)
            do j = 1, merge(edim, 0, param == 1)
               if (.not. allocated(error)) call sc%get_real(dum, kw, error)
            end do
            if (allocated(error)) return
            lo = min(lo, [mesh%x(:, i), z]); hi = max(hi, [mesh%x(:, i), z])
            if (abs(z) > zmax) then
               zmax = abs(z); zline = sc%tok_line; ztag = mesh%node_id(i)
            end if
         end do
         k = k + nb
      end do
      if (k /= nnode) then
         call sc%fail(error, kw, itoa(nnode)//' nodes announced, '//itoa(k)//' found')
         return
      end if
      call expect(sc, '$EndNodes', error)
      if (allocated(error)) return
      if (zmax > 1.0e-12_wp*maxval(hi - lo)) then
         sc%tok_line = zline
         call sc%fail(error, kw, 'node '//itoa(ztag)//' is out of the plane z = 0;'// &
            ' PECPLAS meshes are 2D (x, y) or (r, z) in the Gmsh x-y plane')
         return
      end if
      call g%nodes%build_ids(mesh%node_id, 'Gmsh node tag', error)
      if (allocated(error)) then
         error%file = sc%path; error%line = line0; error%keyword = kw
      end if
   end subroutine read_nodes

   !> Entity blocks "dim tag type n", then n lines "element-tag node-tags...". Blocks that
   !> feed no set are skipped line by line (their type need not be known).
   subroutine read_elements(sc, g, error)
      type(scanner_t), intent(inout) :: sc
      type(gmsh_data_t), intent(inout) :: g
      type(error_t), allocatable, intent(out) :: error
      character(len=*), parameter :: kw = '$Elements'
      integer :: h(4), nblock, b, edim, gtype, nb, ie, npe, i, j, nb0, nc0, tag, nel, seen
      call get_ints(sc, kw, h, error)
      if (allocated(error)) return
      nblock = h(1); nel = h(2); seen = 0
      ! an element takes at least 4 bytes ("t n" + newline), a block header 8
      if (nblock < 0 .or. nel < 0 .or. nel > sc%remaining()/4 .or. &
          nblock > sc%remaining()/8) then
         call sc%fail(error, kw, itoa(nblock)//' blocks and '//itoa(nel)// &
            ' elements announced, but the rest of the file ('//itoa64(sc%remaining())// &
            ' bytes) cannot hold them (truncated file or wrong count?)')
         return
      end if
      do b = 1, nblock
         call get_ints(sc, kw, h, error)
         if (allocated(error)) return
         edim = h(1); gtype = h(3); nb = h(4)
         if (nb < 0 .or. seen + nb > nel) then
            call sc%fail(error, kw, 'bad entity block header: '//itoa(nb)//' elements, '// &
               itoa(seen)//' already read of the '//itoa(nel)//' announced')
            return
         end if
         seen = seen + nb
         ie = 0
         if (edim >= 0 .and. edim <= 2) ie = g%ents(edim)%lookup%index(h(2))
         if (.not. g%used(edim, ie)) then
            call sc%skip_lines(nb, kw, error)
            if (allocated(error)) return
            cycle
         end if
         npe = nodes_per_element(edim, gtype)
         if (npe == 0) then
            call sc%fail(error, kw, 'Gmsh element type '//itoa(gtype)// &
               ' is not supported on a '//unsupported_hint(edim))
            return
         end if
         nb0 = g%nel; nc0 = g%nconn
         call g%add_block(edim, ie, gtype, nb, npe)
         do i = 1, nb
            call sc%get_int(g%el_id(nb0 + i), kw, error)
            if (allocated(error)) return
            do j = 1, npe
               call sc%get_int(tag, kw, error)
               if (allocated(error)) return
               g%conn(nc0 + j) = g%nodes%index(tag)
               if (g%conn(nc0 + j) == 0) then
                  call sc%fail(error, kw, 'element '//itoa(g%el_id(nb0 + i))// &
                     ' refers to node '//itoa(tag)//', which is not in $Nodes')
                  return
               end if
            end do
            nc0 = nc0 + npe
         end do
      end do
      if (seen /= nel) then
         call sc%fail(error, kw, itoa(nel)//' elements announced, '//itoa(seen)//' found')
         return
      end if
      call expect(sc, '$EndElements', error)
   end subroutine read_elements

   pure function itoa64(n) result(s)
      integer(int64), intent(in) :: n
      character(len=:), allocatable :: s
      character(len=24) :: buf
      write (buf, '(i0)') n
      s = trim(buf)
   end function itoa64

   pure function unsupported_hint(edim) result(s)
      integer, intent(in) :: edim
      character(len=:), allocatable :: s
      select case (edim)
      case (2)
         s = 'surface; use 2 (T3), 9 (T6), 3 (Q4) or 16 (Q8), e.g. Mesh.ElementOrder = 2'// &
             ' with Mesh.SecondOrderIncomplete = 1 for 8-node quadrangles'
      case (1)
         s = 'curve; use 1 (2-node line) or 8 (3-node line)'
      case default
         s = 'point; use 15'
      end select
   end function unsupported_hint

   !> Skips an unknown section up to its "$End..." line.
   subroutine skip_section(sc, section, error)
      type(scanner_t), intent(inout) :: sc
      character(len=*), intent(in) :: section
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: end_name
      end_name = '$End'//section(2:)
      do while (sc%next())
         if (sc%buf(sc%t1:sc%t2) == end_name) return
      end do
      call sc%fail(error, section, 'unexpected end of file: no '//end_name//' (truncated?)')
   end subroutine skip_section

   !> The next token must be `word` (a section end); anything else means wrong counts.
   subroutine expect(sc, word, error)
      type(scanner_t), intent(inout) :: sc
      character(len=*), intent(in) :: word
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: w
      call sc%get_word(w, word, error)
      if (allocated(error)) return
      if (w /= word) call sc%fail(error, word, 'expected '//word//', got '''//w// &
         ''' (counts do not match the data?)')
   end subroutine expect

   !> Reads size(v) integers.
   subroutine get_ints(sc, kw, v, error)
      type(scanner_t), intent(inout) :: sc
      character(len=*), intent(in) :: kw
      integer, intent(out) :: v(:)
      type(error_t), allocatable, intent(out) :: error
      integer :: i
      v = 0
      do i = 1, size(v)
         call sc%get_int(v(i), kw, error)
         if (allocated(error)) return
      end do
   end subroutine get_ints

end module pecplas_io_mesh_gmsh
