//! The project as a whole: the book's includes, the source layout, the scene files and their errors, the film and the main binary, the grader.

mod book;
mod book_numbers;
mod edge_values;
mod fifo;
mod figures;
mod film_and_main;
mod fuzz;
mod glossary;
mod grader_hints;
mod grader_hostile;
mod grader_states;
mod grading;
mod hostile;
mod hostile_bvh;
mod layout;
mod live_student;
mod memory;
mod mutants;
mod non_square;
mod obj_quirks;
mod outputs;
mod reports;
mod sample_limit;
mod scene_docs;
mod scene_errors;
mod unit;
