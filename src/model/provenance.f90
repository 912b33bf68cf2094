!> Where each node, element and joint of a model was defined (deck file and line), so that
!> a check after reading (geometry, a singular stiffness, a failing element) can name the
!> line as "file:line: [KEYWORD] message". Imported meshes point at their *MESH line.
module pecplas_model_provenance
   use pecplas_base_error, only: error_t, ERR_INTERNAL, ERR_INPUT
   implicit none (type, external)
   private

   public :: provenance_t, place_t

   !> A deck position: index into provenance_t%files, line (0: unknown) and the keyword
   !> in force there.
   type :: place_t
      integer :: file = 0, line = 0
      character(len=16) :: keyword = ''
   end type place_t

   type :: file_name_t
      character(len=:), allocatable :: path
   end type file_name_t

   !> The places of the members of one set and the keyword that defined them.
   type :: set_places_t
      character(len=:), allocatable :: keyword
      type(place_t), allocatable :: at(:)
   end type set_places_t

   type :: provenance_t
      type(file_name_t), allocatable :: files(:)
      !> nodes(i): place of internal node i (nodes added later, e.g. split for joints, have
      !> none); esets(s)%at(e) and joint_sets(s)%at(e) for elements and joints.
      type(place_t), allocatable :: nodes(:)
      type(set_places_t), allocatable :: esets(:), joint_sets(:)
   contains
      procedure :: place => provenance_place
      procedure :: element => provenance_element
      procedure :: joint => provenance_joint
      procedure :: node => provenance_node
      procedure :: locate => provenance_locate
      procedure :: text => provenance_text
   end type provenance_t

contains

   !> The place of `file`, `line`, adding the file name on first use.
   function provenance_place(this, file, line) result(p)
      class(provenance_t), intent(inout) :: this
      character(len=*), intent(in) :: file
      integer, intent(in) :: line
      type(place_t) :: p
      type(file_name_t), allocatable :: tmp(:)
      integer :: i, n
      if (.not. allocated(this%files)) allocate (this%files(0))
      n = size(this%files)
      p%line = line
      do i = 1, n
         if (this%files(i)%path == file) then
            p%file = i
            return
         end if
      end do
      allocate (tmp(n + 1))
      tmp(1:n) = this%files
      tmp(n + 1)%path = file
      call move_alloc(tmp, this%files)
      p%file = n + 1
   end function provenance_place

   !> Place and keyword of element e of element set s (line 0 when unknown).
   subroutine provenance_element(this, s, e, p, keyword)
      class(provenance_t), intent(in) :: this
      integer, intent(in) :: s, e
      type(place_t), intent(out) :: p
      character(len=:), allocatable, intent(out) :: keyword
      call from_sets(this%esets, s, e, p, keyword)
   end subroutine provenance_element

   !> Place and keyword of joint e of joint set s (line 0 when unknown).
   subroutine provenance_joint(this, s, e, p, keyword)
      class(provenance_t), intent(in) :: this
      integer, intent(in) :: s, e
      type(place_t), intent(out) :: p
      character(len=:), allocatable, intent(out) :: keyword
      call from_sets(this%joint_sets, s, e, p, keyword)
   end subroutine provenance_joint

   subroutine from_sets(sets, s, e, p, keyword)
      type(set_places_t), allocatable, intent(in) :: sets(:)
      integer, intent(in) :: s, e
      type(place_t), intent(out) :: p
      character(len=:), allocatable, intent(out) :: keyword
      keyword = ''
      if (.not. allocated(sets)) return
      if (s < 1 .or. s > size(sets)) return
      if (.not. allocated(sets(s)%at)) return
      if (e < 1 .or. e > size(sets(s)%at)) return
      p = sets(s)%at(e)
      keyword = sets(s)%keyword
   end subroutine from_sets

   !> Place of internal node i (line 0 when unknown).
   pure type(place_t) function provenance_node(this, i) result(p)
      class(provenance_t), intent(in) :: this
      integer, intent(in) :: i
      if (.not. allocated(this%nodes)) return
      if (i < 1 .or. i > size(this%nodes)) return
      p = this%nodes(i)
   end function provenance_node

   !> Gives `error` the deck position `p` and `keyword` unless it already names a line.
   !> A deck position makes an internal or run error an input error only when `as_input`.
   subroutine provenance_locate(this, error, p, keyword, as_input)
      class(provenance_t), intent(in) :: this
      type(error_t), intent(inout) :: error
      type(place_t), intent(in) :: p
      character(len=*), intent(in) :: keyword
      logical, intent(in), optional :: as_input
      if (error%line > 0 .or. p%line <= 0 .or. p%file <= 0) return
      if (p%file > size(this%files)) return
      error%file = this%files(p%file)%path
      error%line = p%line
      error%keyword = keyword
      if (present(as_input)) then
         if (as_input .and. error%kind == ERR_INTERNAL) error%kind = ERR_INPUT
      end if
   end subroutine provenance_locate

   !> "file:line" of `p`, '' when unknown.
   function provenance_text(this, p) result(s)
      class(provenance_t), intent(in) :: this
      type(place_t), intent(in) :: p
      character(len=:), allocatable :: s
      character(len=16) :: buf
      s = ''
      if (p%line <= 0 .or. p%file <= 0 .or. .not. allocated(this%files)) return
      if (p%file > size(this%files)) return
      write (buf, '(i0)') p%line
      s = this%files(p%file)%path//':'//trim(buf)
   end function provenance_text

end module pecplas_model_provenance
