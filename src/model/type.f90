!> The whole problem read from a deck: mesh, materials, supports, load patterns, steps
!> and options. Built by the deck reader, read (intent(in)) by assembly and the driver.
module pecplas_model_type
   use pecplas_model_mesh, only: mesh_t
   use pecplas_model_loads, only: load_pattern_t, step_t, support_t
   use pecplas_model_options, only: analysis_t, solver_options_t, output_options_t
   use pecplas_massif_materials_type, only: material_box_t
   use pecplas_model_joints, only: joint_set_t
   use pecplas_model_plates, only: plate_set_t
   use pecplas_model_initial, only: initial_stress_t
   use pecplas_joints_laws_type, only: interface_law_box_t
   use pecplas_model_contact, only: katona_contact_t
   use pecplas_model_provenance, only: provenance_t
   use pecplas_base_warnings, only: warnings_t
   use pecplas_base_units, only: units_t
   use pecplas_model_adapt_request, only: adapt_request_t
   use pecplas_water_type, only: water_model_t
   use pecplas_model_anchors, only: anchor_set_t
   implicit none (type, external)
   private

   public :: model_t

   type :: model_t
      character(len=:), allocatable :: title
      !> The *UNITS line as written (e.g. "kN, m, kPa") and the units read from it (checked,
      !> written next to every results dataset, never used to convert).
      character(len=:), allocatable :: units
      type(units_t) :: unit_system
      !> Path of the main deck and the full deck text (includes expanded) for provenance.
      character(len=:), allocatable :: deck_file, deck_text
      type(analysis_t) :: analysis
      type(mesh_t) :: mesh
      type(material_box_t), allocatable :: materials(:)
      !> Interface laws (*INTERFACE_LAW) and joint element sets (*JOINTS). A law of
      !> TYPE=KATONA is no constitutive law: it is kept in `contacts`, and the joint sets
      !> that use it are Katona contact sets (joint_set_t%is_katona).
      type(interface_law_box_t), allocatable :: laws(:)
      type(katona_contact_t), allocatable :: contacts(:)
      type(joint_set_t), allocatable :: joint_sets(:)
      !> Anchors and struts (*ANCHOR): bars on the translations of their nodes.
      type(anchor_set_t), allocatable :: anchors(:)
      !> Plate (beam) sets (*PLATE) and the rotation of each node: node_rotation(i) = r > 0
      !> when node i carries a plate (its rotation is column nnode + r of the nodal arrays,
      !> pecplas_model_columns), 0 otherwise. Empty without plates.
      type(plate_set_t), allocatable :: plates(:)
      integer, allocatable :: node_rotation(:)
      type(support_t) :: supports
      !> Initial stresses (*INITIAL_STRESS), applied in order (later entries overwrite).
      type(initial_stress_t), allocatable :: initial_stresses(:)
      type(load_pattern_t), allocatable :: patterns(:)
      type(step_t), allocatable :: steps(:)
      type(solver_options_t) :: solver
      type(output_options_t) :: output
      !> *ADAPT: run the adaptive loop (pecplas_adapt_adapt) instead of one analysis.
      type(adapt_request_t) :: adapt
      !> Groundwater: phreatic levels, drainage of the materials, dry sets (*WATER).
      type(water_model_t) :: water
      !> Deck line of every node, element and joint (for checks after reading).
      type(provenance_t) :: provenance
      !> Suspicious input found while reading and checking (pecplas_base_warnings).
      type(warnings_t) :: warnings
   end type model_t

end module pecplas_model_type
